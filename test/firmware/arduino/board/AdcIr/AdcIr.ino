// AdcIr - every 100 ms, for each IR channel A0..A3: the dark reading (both
// emitters off), then the lit one (that channel's emitter pin high, read
// 50 us later), printed `IR ch dark lit ms`. UKMARSBOT with the advanced
// wall sensor (mazerunner-core ORION): A0 right front, A1 right diagonal,
// A2 left diagonal, A3 left front; D11 lights the front pair, D12 the
// diagonal pair.
const uint8_t EMIT_FRONT = 11, EMIT_DIAG = 12;

static uint8_t emitter_of(uint8_t ch) { return ch == 0 || ch == 3 ? EMIT_FRONT : EMIT_DIAG; }

void setup() {
  Serial.begin(115200);
  pinMode(EMIT_FRONT, OUTPUT);
  pinMode(EMIT_DIAG, OUTPUT);
  digitalWrite(EMIT_FRONT, LOW);
  digitalWrite(EMIT_DIAG, LOW);
  Serial.println(F("ADCIR"));
}

void loop() {
  static unsigned long next = 100;
  while (millis() < next) {}
  next += 100;
  for (uint8_t ch = 0; ch < 4; ch++) {
    int dark = analogRead(A0 + ch);
    digitalWrite(emitter_of(ch), HIGH);
    delayMicroseconds(50);
    int lit = analogRead(A0 + ch);
    digitalWrite(emitter_of(ch), LOW);
    delayMicroseconds(500); // the detector settles dark again
    Serial.print(F("IR "));
    Serial.print(ch);
    Serial.print(' ');
    Serial.print(dark);
    Serial.print(' ');
    Serial.print(lit);
    Serial.print(' ');
    Serial.println(millis());
  }
}
