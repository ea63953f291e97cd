// AdcTimerTrigger - a test sketch for the board emulation (test/cli/cli_board.sh):
// selects the Timer0-overflow ADC auto-trigger (ADCSRB.ADTS = 4), which
// simavr 1.6 does not emulate: mmsim must stop with one line, exit 2.
void setup() {
  ADCSRB = 4;
  ADCSRA |= _BV(ADEN) | _BV(ADATE);
}

void loop() {}
