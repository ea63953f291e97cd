// EncoderCount - a test sketch for the board emulation (test/cli/cli_board.sh),
// built for the Nano: counts every edge of both encoders with INT0/INT1 on
// change (the board feeds D2/D3 with A xor B, B to D4/D5) and decodes the
// direction as mazerunner-core's encoders.h does with the board's wiring
// (left counts forward with polarity -1, right with +1). Drives forward at
// full speed for 250 ms, stops, backs up at 60/255 for 300 ms, stops, and
// 700 ms later prints "COUNTS L R EDGES EL ER".
const uint8_t L_DIR = 7, R_DIR = 8, L_PWM = 9, R_PWM = 10;
volatile long count_l, count_r, edges_l, edges_r;
volatile bool la, lb, ra, rb;

void isr_left() {
  bool b = digitalRead(4), a = digitalRead(2) ^ b;
  count_l -= (la ^ b) - (a ^ lb);
  la = a;
  lb = b;
  edges_l++;
}

void isr_right() {
  bool b = digitalRead(5), a = digitalRead(3) ^ b;
  count_r += (ra ^ b) - (a ^ rb);
  ra = a;
  rb = b;
  edges_r++;
}

void drive(int left, int right) {  // -255..255, forward positive
  digitalWrite(L_DIR, left < 0);
  digitalWrite(R_DIR, right >= 0);
  analogWrite(L_PWM, abs(left));
  analogWrite(R_PWM, abs(right));
}

void setup() {
  Serial.begin(115200);
  pinMode(2, INPUT);
  pinMode(3, INPUT);
  pinMode(4, INPUT);
  pinMode(5, INPUT);
  pinMode(L_DIR, OUTPUT);
  pinMode(R_DIR, OUTPUT);
  pinMode(L_PWM, OUTPUT);
  pinMode(R_PWM, OUTPUT);
  lb = digitalRead(4);
  la = digitalRead(2) ^ lb;
  rb = digitalRead(5);
  ra = digitalRead(3) ^ rb;
  attachInterrupt(digitalPinToInterrupt(2), isr_left, CHANGE);
  attachInterrupt(digitalPinToInterrupt(3), isr_right, CHANGE);
  drive(255, 255);
  delay(250);
  drive(0, 0);
  delay(500);
  drive(-60, -60);
  delay(300);
  drive(0, 0);
  delay(700);
  noInterrupts();
  long l = count_l, r = count_r, el = edges_l, er = edges_r;
  interrupts();
  Serial.print("COUNTS ");
  Serial.print(l);
  Serial.print(' ');
  Serial.print(r);
  Serial.print(" EDGES ");
  Serial.print(el);
  Serial.print(' ');
  Serial.println(er);
}

void loop() {}
