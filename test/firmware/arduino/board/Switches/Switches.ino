// Switches - A6 (the function switches and the button on a resistor ladder)
// read every 50 ms, printed `SW raw ms`.
void setup() {
  Serial.begin(115200);
  Serial.println(F("SWITCHES"));
}

void loop() {
  static unsigned long next = 50;
  while (millis() < next) {}
  next += 50;
  int raw = analogRead(A6);
  Serial.print(F("SW "));
  Serial.print(raw);
  Serial.print(' ');
  Serial.println(millis());
}
