// HandCount - a test sketch for the board emulation (test/cli/cli_board_push.sh),
// built for the Nano: an encoder-calibration sketch. The motors are never
// driven (a person rolls or carries the robot by hand). Counts every edge of
// both encoders with INT0/INT1 on change (the board feeds D2/D3 with A xor
// B, B to D4/D5) and decodes the direction as mazerunner-core's encoders.h
// does with the board's wiring (left counts forward with polarity -1, right
// with +1); every 100 ms prints "HC MS L R EL ER": the time in ms since
// setup, the signed counts and the edges seen on each side.
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

unsigned long next_ms;

void setup() {
  Serial.begin(115200);
  pinMode(2, INPUT);
  pinMode(3, INPUT);
  pinMode(4, INPUT);
  pinMode(5, INPUT);
  lb = digitalRead(4);
  la = digitalRead(2) ^ lb;
  rb = digitalRead(5);
  ra = digitalRead(3) ^ rb;
  attachInterrupt(digitalPinToInterrupt(2), isr_left, CHANGE);
  attachInterrupt(digitalPinToInterrupt(3), isr_right, CHANGE);
  next_ms = millis();
}

void loop() {
  if ((long)(millis() - next_ms) < 0) return;
  next_ms += 100;
  noInterrupts();
  long l = count_l, r = count_r, el = edges_l, er = edges_r;
  interrupts();
  Serial.print("HC ");
  Serial.print(millis());
  Serial.print(' ');
  Serial.print(l);
  Serial.print(' ');
  Serial.print(r);
  Serial.print(' ');
  Serial.print(el);
  Serial.print(' ');
  Serial.println(er);
}
