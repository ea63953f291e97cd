// The second tab: joined after MultiTab.ino (tabs after the main one go in
// alphabetical order), so report() is used before its definition.

// the values from index first on, summed (a default argument: a function
// with one gets no generated prototype, so it is defined before its use)
long sum_values(unsigned first = 0) {
  long sum = 0;
  for (unsigned i = first; i < sizeof VALUES / sizeof VALUES[0]; i++) sum += VALUES[i];
  return sum;
}

// what: a label; n: a count
void report(const __FlashStringHelper *what, unsigned n) {
  Serial.print(F("REPORT "));
  Serial.print(what);
  Serial.print(' ');
  Serial.print(n);
  Serial.print(F(" sum "));
  Serial.println(sum_values());
}
