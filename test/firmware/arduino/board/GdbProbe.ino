// GdbProbe - a test sketch for debugging on the emulated board
// (test/cli/cli_gdb.sh: mmsim --gdb PORT and a scripted avr-gdb), built for the
// Nano with debug info (-g). Drives forward at 80/255 for 300 ms, then
// stops; every 100 ms up to five times probe_tick() adds one to probe_count
// and prints "COUNT n". The script breaks on probe_tick, reads
// probe_count, steps over its first line and reads it again.
const uint8_t L_DIR = 7, R_DIR = 8, L_PWM = 9, R_PWM = 10;
volatile uint16_t probe_count;

// not inlined: avr-gdb breaks on it by name and steps through its lines
__attribute__((noinline)) void probe_tick() {
  probe_count++;
  Serial.print("COUNT ");
  Serial.println(probe_count);
}

void setup() {
  Serial.begin(115200);
  pinMode(L_DIR, OUTPUT);
  pinMode(R_DIR, OUTPUT);
  pinMode(L_PWM, OUTPUT);
  pinMode(R_PWM, OUTPUT);
  digitalWrite(L_DIR, LOW);   // forward: left DIR low, right DIR high
  digitalWrite(R_DIR, HIGH);
  analogWrite(L_PWM, 80);
  analogWrite(R_PWM, 80);
}

void loop() {
  static unsigned long next_ms = 100;
  unsigned long now = millis();
  if (now >= 300) {
    analogWrite(L_PWM, 0);
    analogWrite(R_PWM, 0);
  }
  if (now >= next_ms && probe_count < 5) {
    next_ms += 100;
    probe_tick();
  }
}
