// SleepLevel - a test sketch for the board emulation (test/cli/cli_board.sh),
// built for the Nano: sleeps (idle mode) in loop(), woken by Timer0's
// overflow and by INT1, while the robot drives and the encoder pins go low
// and high. INT0 stays in its reset low-level mode, not enabled (simavr
// checks it at every cycle while D2 is low, which shortens each sleep);
// INT1 is enabled on any change. Prints the wake-ups, INT1's runs and
// Timer0's count folded over every wake-up, so their cycles show.
#include <avr/sleep.h>
const uint8_t L_DIR = 7, R_DIR = 8, L_PWM = 9, R_PWM = 10;
volatile unsigned long runs1;
unsigned long wakes;
uint16_t stamp;

void isr1() { runs1++; }

void setup() {
  Serial.begin(115200);
  pinMode(L_DIR, OUTPUT);
  pinMode(R_DIR, OUTPUT);
  pinMode(L_PWM, OUTPUT);
  pinMode(R_PWM, OUTPUT);
  digitalWrite(L_DIR, LOW);
  digitalWrite(R_DIR, HIGH);
  analogWrite(L_PWM, 80);
  analogWrite(R_PWM, 80);
  attachInterrupt(1, isr1, CHANGE);
  set_sleep_mode(SLEEP_MODE_IDLE);
}

void loop() {
  sleep_mode();
  wakes++;
  stamp = stamp * 31 + TCNT0;
  static unsigned long last_print_ms;
  if (millis() - last_print_ms >= 250) {
    last_print_ms = millis();
    Serial.print("WAKES ");
    Serial.print(wakes);
    Serial.print(' ');
    Serial.print(runs1);
    Serial.print(' ');
    Serial.println(stamp);
    Serial.flush();
  }
}
