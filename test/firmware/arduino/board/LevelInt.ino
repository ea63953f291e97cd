// LevelInt - a test sketch for the board emulation (test/cli/cli_board.sh),
// built for the Nano: INT0/INT1 in their low-level mode, which simavr
// checks at every instruction boundary while the pin is low and which the
// simulator runs without that check (sim/board/extint_level.h). The robot
// drives forward at 80/255 so the encoder pins (D2, D3) go low and high.
// Phase 1 (INT0 and INT1 disabled): samples EIFR's INTF0/INTF1 after
// clearing them, with interrupts on and off, 2000 times. Phase 2: INT0
// enabled in low-level mode (attachInterrupt LOW): its ISR runs again and
// again while D2 is low; the ISR detaches itself after 200 runs and the
// sketch re-attaches it every 20 ms. Prints the tallies and Timer0's count
// folded over every ISR run, so their timing shows.
const uint8_t L_DIR = 7, R_DIR = 8, L_PWM = 9, R_PWM = 10;
volatile unsigned long runs0, batches;
volatile uint16_t stamp;

void isr0() {
  runs0++;
  stamp = stamp * 31 + TCNT0;
  if (runs0 % 200 == 0) {
    detachInterrupt(0);
    batches++;
  }
}

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
  delay(100);
  unsigned long set_on = 0, set_off = 0, set_after = 0, low = 0;
  for (int i = 0; i < 2000; i++) {
    if (!(PIND & 4)) low++;
    EIFR = 3;  // write-one-to-clear on the chip; simavr stores the value
    EIFR = 0;
    set_on += (EIFR & 3) != 0;
    cli();
    EIFR = 0;
    set_off += (EIFR & 3) != 0;
    sei();
    set_after += (EIFR & 3) != 0;
    delayMicroseconds(97);
  }
  Serial.print("FLAGS low ");
  Serial.print(low);
  Serial.print(" on ");
  Serial.print(set_on);
  Serial.print(" off ");
  Serial.print(set_off);
  Serial.print(" after ");
  Serial.println(set_after);
}

void loop() {
  static unsigned long last_ms;
  if (millis() - last_ms >= 20) {
    last_ms = millis();
    cli();
    EIFR = 0;  // simavr keeps INTF0 set from phase 1 otherwise, and then never raises INT0
    attachInterrupt(0, isr0, LOW);
    sei();
  }
  static unsigned long last_print_ms;
  if (millis() - last_print_ms >= 250) {
    last_print_ms = millis();
    noInterrupts();
    unsigned long r = runs0, b = batches;
    uint16_t s = stamp;
    interrupts();
    Serial.print("INT0 ");
    Serial.print(r);
    Serial.print(' ');
    Serial.print(b);
    Serial.print(' ');
    Serial.println(s);
  }
}
