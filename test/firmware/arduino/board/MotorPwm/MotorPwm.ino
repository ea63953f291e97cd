// MotorPwm - Timer1 PWM on D9 (OC1A, left) and D10 (OC1B, right) with the
// direction on D7/D8, in three Timer1 set-ups, each at 25 % duty (50 %
// is ~2 m/s on a full battery: too fast to stop in a 16x16 maze):
//   fwd: analogWrite (the core's Timer1: phase-correct 8-bit, clk/64), 1 s
//   rev: fast PWM 8-bit at clk/1 (mazerunner-core's 31.25 kHz), 0.6 s back
//   icr: fast PWM with TOP = ICR1 = 799 (mode 14, 20 kHz), OCR = 200, 0.5 s
// with 0.5 s stopped after each. After each phase: `PHASE name ms left
// right` with the encoder counts (forward positive), then `DONE`.
const uint8_t L_DIR = 7, R_DIR = 8, L_PWM = 9, R_PWM = 10;
const uint8_t L_INT = 2, R_INT = 3, L_B = 4, R_B = 5;
// mazerunner-core + ORION: MOTOR_LEFT_POLARITY 1, MOTOR_RIGHT_POLARITY -1
const uint8_t L_FWD = LOW, R_FWD = HIGH;

volatile long enc_left, enc_right;

// mazerunner-core's decoding (encoders.h): the interrupt pin carries A xor B
static void isr_left() {
  static bool oldA, oldB;
  bool newB = digitalRead(L_B);
  bool newA = digitalRead(L_INT) ^ newB;
  enc_left -= (oldA ^ newB) - (newA ^ oldB); // ENCODER_LEFT_POLARITY -1
  oldA = newA;
  oldB = newB;
}
static void isr_right() {
  static bool oldA, oldB;
  bool newB = digitalRead(R_B);
  bool newA = digitalRead(R_INT) ^ newB;
  enc_right += (oldA ^ newB) - (newA ^ oldB);
  oldA = newA;
  oldB = newB;
}

static void report(const char *phase) {
  long l, r;
  noInterrupts();
  l = enc_left;
  r = enc_right;
  interrupts();
  Serial.print(F("PHASE "));
  Serial.print(phase);
  Serial.print(' ');
  Serial.print(millis());
  Serial.print(' ');
  Serial.print(l);
  Serial.print(' ');
  Serial.println(r);
}

static void stop_motors() {
  analogWrite(L_PWM, 0); // digitalWrite LOW: the COM1x bits off
  analogWrite(R_PWM, 0);
}

static void direction(bool forward) {
  digitalWrite(L_DIR, forward ? L_FWD : !L_FWD);
  digitalWrite(R_DIR, forward ? R_FWD : !R_FWD);
}

void setup() {
  Serial.begin(115200);
  pinMode(L_DIR, OUTPUT);
  pinMode(R_DIR, OUTPUT);
  pinMode(L_PWM, OUTPUT);
  pinMode(R_PWM, OUTPUT);
  pinMode(L_INT, INPUT);
  pinMode(R_INT, INPUT);
  pinMode(L_B, INPUT);
  pinMode(R_B, INPUT);
  attachInterrupt(digitalPinToInterrupt(L_INT), isr_left, CHANGE);
  attachInterrupt(digitalPinToInterrupt(R_INT), isr_right, CHANGE);
  Serial.println(F("MOTORPWM"));

  // analogWrite as the core sets Timer1 up (wiring.c: WGM10, CS11|CS10)
  direction(true);
  analogWrite(L_PWM, 64);
  analogWrite(R_PWM, 64);
  delay(1000);
  stop_motors();
  report("fwd");
  delay(500);
  report("fwd_stop");

  // fast PWM 8-bit (mode 5), clk/1: 31.25 kHz
  direction(false);
  TCCR1A = _BV(COM1A1) | _BV(COM1B1) | _BV(WGM10);
  TCCR1B = _BV(WGM12) | _BV(CS10);
  OCR1A = 64;
  OCR1B = 64;
  delay(600);
  stop_motors();
  report("rev");
  delay(500);
  report("rev_stop");

  // fast PWM, TOP = ICR1 (mode 14), clk/1: 16 MHz / 800 = 20 kHz
  direction(true);
  ICR1 = 799;
  OCR1A = 200;
  OCR1B = 200;
  TCCR1A = _BV(COM1A1) | _BV(COM1B1) | _BV(WGM11);
  TCCR1B = _BV(WGM13) | _BV(WGM12) | _BV(CS10);
  delay(500);
  stop_motors();
  report("icr");
  delay(500);
  report("icr_stop");
  Serial.println(F("DONE"));
}

void loop() {}
