// HudPanel - for the viewer's board panel (test/cli/cli_view_board.sh): prints a
// banner, lights the builtin LED (D13; the user LED on D6 stays dark), then
// reads A6 every 20 ms and prints `SW n` each time the decoded setting
// changes (n 0..15 with mazerunner-core's adc_thesholds, 16: the button).
static const int thr[17] = {660, 647, 630, 614, 590, 570, 545, 522, 461, 429, 385, 343, 271, 212, 128, 44, 0};

static int decode(int adc) {
  if (adc > 800) return 16;
  for (int i = 0; i < 16; i++)
    if (adc > (thr[i] + thr[i + 1]) / 2) return i;
  return -1;
}

void setup() {
  Serial.begin(115200);
  pinMode(13, OUTPUT);
  pinMode(6, OUTPUT);
  digitalWrite(13, HIGH);
  digitalWrite(6, LOW);
  Serial.println(F("HUD PANEL TEST"));
  Serial.println(F("hello from the board"));
}

void loop() {
  static int last = -2;
  static unsigned long next = 20;
  while (millis() < next) {}
  next += 20;
  int n = decode(analogRead(A6));
  if (n != last) {
    Serial.print(F("SW "));
    Serial.println(n);
    last = n;
  }
}
