// Encoders - both wheels forward at a fixed PWM (analogWrite 64, 25 %) for
// 1 s, then stopped; the INT0/INT1 edges (A xor B on D2/D3) counted with
// the direction from B on D4/D5 as mazerunner-core's encoders.h does, every
// 100 ms `ENC left N right M` (forward positive), `DONE` at 2 s.
const uint8_t L_DIR = 7, R_DIR = 8, L_PWM = 9, R_PWM = 10;
const uint8_t L_INT = 2, R_INT = 3, L_B = 4, R_B = 5;
const uint8_t L_FWD = LOW, R_FWD = HIGH; // ORION's motor polarities
const uint8_t PWM = 64;

volatile long enc_left, enc_right;
volatile unsigned long isr_left_n, isr_right_n;

static void isr_left() {
  static bool oldA, oldB;
  bool newB = digitalRead(L_B);
  bool newA = digitalRead(L_INT) ^ newB;
  enc_left -= (oldA ^ newB) - (newA ^ oldB); // ENCODER_LEFT_POLARITY -1
  oldA = newA;
  oldB = newB;
  isr_left_n++;
}
static void isr_right() {
  static bool oldA, oldB;
  bool newB = digitalRead(R_B);
  bool newA = digitalRead(R_INT) ^ newB;
  enc_right += (oldA ^ newB) - (newA ^ oldB);
  oldA = newA;
  oldB = newB;
  isr_right_n++;
}

static void print_counts(void) {
  long l, r;
  unsigned long nl, nr;
  noInterrupts();
  l = enc_left;
  r = enc_right;
  nl = isr_left_n;
  nr = isr_right_n;
  interrupts();
  Serial.print(F("ENC left "));
  Serial.print(l);
  Serial.print(F(" right "));
  Serial.print(r);
  Serial.print(F(" isr "));
  Serial.print(nl);
  Serial.print(' ');
  Serial.print(nr);
  Serial.print(F(" ms "));
  Serial.println(millis());
}

void setup() {
  Serial.begin(115200);
  pinMode(L_DIR, OUTPUT);
  pinMode(R_DIR, OUTPUT);
  pinMode(L_INT, INPUT);
  pinMode(R_INT, INPUT);
  pinMode(L_B, INPUT);
  pinMode(R_B, INPUT);
  attachInterrupt(digitalPinToInterrupt(L_INT), isr_left, CHANGE);
  attachInterrupt(digitalPinToInterrupt(R_INT), isr_right, CHANGE);
  Serial.println(F("ENCODERS"));
  digitalWrite(L_DIR, L_FWD);
  digitalWrite(R_DIR, R_FWD);
  analogWrite(L_PWM, PWM);
  analogWrite(R_PWM, PWM);
  unsigned long t0 = millis();
  for (int i = 1; i <= 20; i++) {
    while (millis() - t0 < 100UL * i) {}
    if (i == 10) {
      analogWrite(L_PWM, 0);
      analogWrite(R_PWM, 0);
    }
    print_counts();
  }
  Serial.println(F("DONE"));
}

void loop() {}
