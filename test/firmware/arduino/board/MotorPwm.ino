// MotorPwm - a test sketch for the board emulation (test/cli/cli_board.sh),
// built for the Nano: drives both wheels forward through UKMARSBOT's motor
// pins (direction D7/D8, PWM D9/D10 = OC1A/OC1B; the board wires the right
// motor mirrored: forward is DIR low on the left, DIR high on the right),
// first with Arduino's analogWrite (Timer1 8-bit phase-correct PWM), then
// with Timer1 in fast PWM mode 14 (TOP = ICR1), the same duty 40/255, then
// stops. Prints DONE.
const uint8_t L_DIR = 7, R_DIR = 8, L_PWM = 9, R_PWM = 10;

void setup() {
  Serial.begin(115200);
  pinMode(L_DIR, OUTPUT);
  pinMode(R_DIR, OUTPUT);
  pinMode(L_PWM, OUTPUT);
  pinMode(R_PWM, OUTPUT);
  digitalWrite(L_DIR, 0);
  digitalWrite(R_DIR, 1);
  analogWrite(L_PWM, 40);  // 40/255 = 0.157 (phase correct: OCR / TOP)
  analogWrite(R_PWM, 40);
  delay(400);
  // fast PWM, TOP = ICR1 = 1599 (10 kHz): (OCR + 1) / (TOP + 1) = 251 / 1600 = 0.157
  TCCR1A = _BV(COM1A1) | _BV(COM1B1) | _BV(WGM11);
  TCCR1B = _BV(WGM13) | _BV(WGM12) | _BV(CS10);
  ICR1 = 1599;
  OCR1A = 250;
  OCR1B = 250;
  delay(400);
  TCCR1A = 0;  // the pins back to the port: low = stop
  digitalWrite(L_PWM, 0);
  digitalWrite(R_PWM, 0);
  Serial.println("DONE");
}

void loop() {}
