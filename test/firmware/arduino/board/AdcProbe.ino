// AdcProbe - a test sketch for the board emulation (test/cli/cli_board.sh),
// built for the Nano: the ADC in its three ways. At 0.2 s, single
// conversions (analogRead) of the IR detectors A0-A3 with both emitter pins
// (D11 front, D12 diagonal) low, then high; the switch ladder A6 and the
// battery divider A7; then A7 in free-running mode (ADATE, ADTS = 0),
// interrupt driven: the ISR counts conversions and keeps the last. Prints
// "OFF a0 a1 a2 a3 ON a0 a1 a2 a3 SW a6 BAT a7" and "FREE n a7".
volatile uint16_t free_count, free_last;

ISR(ADC_vect) {
  free_last = ADC;
  free_count++;
}

void setup() {
  Serial.begin(115200);
  pinMode(11, OUTPUT);
  pinMode(12, OUTPUT);
  delay(200);
  int off[4], on[4];
  for (int i = 0; i < 4; i++) off[i] = analogRead(i);
  digitalWrite(11, 1);
  digitalWrite(12, 1);
  delayMicroseconds(50);
  for (int i = 0; i < 4; i++) on[i] = analogRead(i);
  digitalWrite(11, 0);
  digitalWrite(12, 0);
  int sw = analogRead(6), bat = analogRead(7);
  Serial.print("OFF");
  for (int i = 0; i < 4; i++) { Serial.print(' '); Serial.print(off[i]); }
  Serial.print(" ON");
  for (int i = 0; i < 4; i++) { Serial.print(' '); Serial.print(on[i]); }
  Serial.print(" SW ");
  Serial.print(sw);
  Serial.print(" BAT ");
  Serial.println(bat);
  // free running on A7 (ADMUX keeps AVCC from analogRead), interrupt driven, 10 ms
  ADMUX = (ADMUX & 0xF0) | 7;
  ADCSRB = 0;
  ADCSRA |= _BV(ADATE) | _BV(ADIE);
  ADCSRA |= _BV(ADSC);
  delay(10);
  ADCSRA &= ~(_BV(ADATE) | _BV(ADIE));
  Serial.print("FREE ");
  Serial.print(free_count);
  Serial.print(' ');
  Serial.println(free_last);
}

void loop() {}
