// EncPoll - a benchmark sketch for the board emulation (bench/run.sh,
// docs/BENCHMARKS.md), built for the Nano: drives both motors forward and
// back at 120/255 (1 s each way, 2 s in all) and counts the encoders' edges
// by reading D2..D5 in loop(), as many example sketches do, printing
// "EDGES L R" once a second. INT0/INT1 are left as reset leaves them
// (EICRA = 0: low level, not enabled in EIMSK); built with -DENCPOLL_EDGE
// (EncPollEdge.elf, the Makefile) they are set to "any change" instead: the
// pair measures what the level mode costs the simulator.
const uint8_t L_DIR = 7, R_DIR = 8, L_PWM = 9, R_PWM = 10;
#ifdef ENCPOLL_EDGE
const bool EDGE_MODE = true;
#else
const bool EDGE_MODE = false;
#endif
long edges_l, edges_r;
uint8_t last_l, last_r;
unsigned long t0_ms, last_print_ms;

void drive(int left, int right) {  // -255..255, forward positive
  digitalWrite(L_DIR, left < 0);
  digitalWrite(R_DIR, right >= 0);
  analogWrite(L_PWM, abs(left));
  analogWrite(R_PWM, abs(right));
}

void setup() {
  Serial.begin(115200);
  for (uint8_t p = 2; p <= 5; p++) pinMode(p, INPUT);
  pinMode(L_DIR, OUTPUT);
  pinMode(R_DIR, OUTPUT);
  pinMode(L_PWM, OUTPUT);
  pinMode(R_PWM, OUTPUT);
  if (EDGE_MODE) EICRA = (1 << ISC00) | (1 << ISC10);  // any change, INT0 and INT1 still disabled
  last_l = digitalRead(2) | digitalRead(4) << 1;
  last_r = digitalRead(3) | digitalRead(5) << 1;
  t0_ms = last_print_ms = millis();
  drive(120, 120);
}

void loop() {
  uint8_t l = digitalRead(2) | digitalRead(4) << 1, r = digitalRead(3) | digitalRead(5) << 1;
  if (l != last_l) edges_l++;
  if (r != last_r) edges_r++;
  last_l = l;
  last_r = r;
  unsigned long now_ms = millis();
  if (now_ms - t0_ms >= 2000) drive(0, 0);
  else if (now_ms - t0_ms >= 1000) drive(-120, -120);
  if (now_ms - last_print_ms >= 1000) {
    last_print_ms = now_ms;
    Serial.print("EDGES ");
    Serial.print(edges_l);
    Serial.print(' ');
    Serial.println(edges_r);
  }
}
