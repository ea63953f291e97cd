// Disc12 - a test sketch for a UKMARSBOT with 12-count encoder discs and
// 20:1 gearmotors (test/cli/cli_board_builds.sh: boards/ukmarsbot-basic-v1.3.ini
// with robots/ukmarsbot-basic-12.ini), built for the Nano. Like older
// UKMARSBOT firmware it works its odometry out from its own #defines: counts
// per motor turn, gear ratio, wheel diameter and track, every edge of A xor B
// counted (INT0/INT1 on change, B read for the direction, the mainboard's
// polarities: the left encoder counts down going forward). It drives forward,
// steered by the count difference, its PWM proportional to the counts still
// to go (a position loop, so it holds the target) until 0.4 s after the mean
// count first reaches DISTANCE_MM's; stops; turns in place (left wheel back,
// right forward) the same way to TURN_DEG's arc; stops. It prints
// "TARGET counts", "FWD ms left right" when it stops, "REST ms left right"
// 0.5 s later; the same for the turn ("TURNTARGET", "TURN", "REST").
// GEAR_RATIO may be given with -D (test/cli/cli_board_builds.sh builds it with
// the 11:1's 11.4 for robots/ukmarsbot-basic-11.ini).
#define ENCODER_COUNTS 12.0 // per motor turn
#ifndef GEAR_RATIO
#define GEAR_RATIO 19.55    // the Pimoroni 20:1's gear train
#endif
#define WHEEL_DIAMETER 32.0 // mm
#define WHEEL_TRACK 75.0    // mm, wheel centre to wheel centre
#define DISTANCE_MM 500.0
#define TURN_DEG 360.0
const float MM_PER_COUNT = PI * WHEEL_DIAMETER / (ENCODER_COUNTS * GEAR_RATIO);
const uint8_t L_DIR = 7, R_DIR = 8, L_PWM = 9, R_PWM = 10;
volatile long count_l, count_r;
volatile bool la, lb, ra, rb;

void isr_left() {
  bool b = digitalRead(4), a = digitalRead(2) ^ b;
  count_l -= (la ^ b) - (a ^ lb);
  la = a;
  lb = b;
}

void isr_right() {
  bool b = digitalRead(5), a = digitalRead(3) ^ b;
  count_r += (ra ^ b) - (a ^ rb);
  ra = a;
  rb = b;
}

void drive(int left, int right) {  // -255..255, forward positive
  digitalWrite(L_DIR, left < 0);
  digitalWrite(R_DIR, right >= 0);
  analogWrite(L_PWM, abs(left));
  analogWrite(R_PWM, abs(right));
}

void counts(long *l, long *r) {
  noInterrupts();
  *l = count_l;
  *r = count_r;
  interrupts();
}

void report(const char *what) {
  long l, r;
  counts(&l, &r);
  Serial.print(what);
  Serial.print(' ');
  Serial.print(millis());
  Serial.print(' ');
  Serial.print(l);
  Serial.print(' ');
  Serial.println(r);
}

// PWM for the counts still to go and the counts moved in the last 5 ms
// period (a PD position loop): at least enough to move, 0 within a count
int position_pwm(long to_go, long moved, int max_pwm) {
  if (to_go >= -1 && to_go <= 1) return 0;
  int pwm = (int)constrain(to_go / 2 - 6 * moved, -max_pwm, max_pwm);
  if (pwm > -12 && pwm < 12) pwm = to_go > 0 ? 12 : -12;
  return pwm;
}

void setup() {
  Serial.begin(115200);
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
  delay(200);
  long l, r;
  const long fwd = (long)(DISTANCE_MM / MM_PER_COUNT + 0.5);
  Serial.print("TARGET ");
  Serial.println(fwd);
  unsigned long until = 0;
  long last = 0;
  for (;; delay(5)) {  // forward, steered by the count difference, every 5 ms
    counts(&l, &r);
    long to_go = fwd - (l + r) / 2;
    if (!until && to_go <= 0) until = millis() + 400;
    if (until && (long)(millis() - until) >= 0) break;
    int pwm = position_pwm(to_go, (l + r) / 2 - last, 60), steer = (int)constrain(4 * (l - r), -15, 15);
    last = (l + r) / 2;
    drive(pwm - steer, pwm + steer);
  }
  drive(0, 0);
  report("FWD");
  delay(500);
  report("REST");
  long l0, r0;
  counts(&l0, &r0);
  // a turn of TURN_DEG moves each wheel pi * track * deg / 360 along its arc
  const long turn = (long)(PI * WHEEL_TRACK * TURN_DEG / 360.0 / MM_PER_COUNT + 0.5);
  Serial.print("TURNTARGET ");
  Serial.println(turn);
  until = 0;
  last = 0;
  for (;; delay(5)) {
    counts(&l, &r);
    long dl = l0 - l, dr = r - r0, to_go = turn - (dl + dr) / 2;
    if (!until && to_go <= 0) until = millis() + 400;
    if (until && (long)(millis() - until) >= 0) break;
    int pwm = position_pwm(to_go, (dl + dr) / 2 - last, 50), steer = (int)constrain(4 * (dl - dr), -15, 15);
    last = (dl + dr) / 2;
    drive(-(pwm - steer), pwm + steer);
  }
  drive(0, 0);
  report("TURN");
  delay(500);
  report("REST");
  Serial.println("DONE");
}

void loop() {}
