// Battery - A7 (the battery through UKMARSBOT's 1:2 divider, R7 = R8) read
// every 100 ms, printed `BAT mv raw ms` with mv = raw * 5000 / 1023 * 2.
void setup() {
  Serial.begin(115200);
  Serial.println(F("BATTERY"));
}

void loop() {
  static unsigned long next = 100;
  while (millis() < next) {}
  next += 100;
  int raw = analogRead(A7);
  long mv = (long)raw * 5000L / 1023L * 2L;
  Serial.print(F("BAT "));
  Serial.print(mv);
  Serial.print(' ');
  Serial.print(raw);
  Serial.print(' ');
  Serial.println(millis());
}
