// AdcOpen - a test sketch for the board emulation (test/cli/cli_board_analog.sh),
// built for the Nano: A4 and A5 as the board file wires them. Reads A4 first
// (nothing converted yet), then A4 right after the battery divider A7 and A5
// right after the switch ladder A6 (an open pin: what the sample-and-hold
// kept), then A4 with its pull-up on and A5 driven low as an output. Prints
// "FIRST a4 BAT a7 A4 a4 SW a6 A5 a5 PULLUP a4 LOW a5".
void setup() {
  Serial.begin(115200);
  delay(50);
  int first = analogRead(4);
  int bat = analogRead(7), a4 = analogRead(4);
  int sw = analogRead(6), a5 = analogRead(5);
  pinMode(A4, INPUT_PULLUP);
  int up = analogRead(4);
  pinMode(A5, OUTPUT);
  digitalWrite(A5, LOW);
  analogRead(7);
  int low = analogRead(5);
  Serial.print("FIRST ");
  Serial.print(first);
  Serial.print(" BAT ");
  Serial.print(bat);
  Serial.print(" A4 ");
  Serial.print(a4);
  Serial.print(" SW ");
  Serial.print(sw);
  Serial.print(" A5 ");
  Serial.print(a5);
  Serial.print(" PULLUP ");
  Serial.print(up);
  Serial.print(" LOW ");
  Serial.println(low);
}

void loop() {}
