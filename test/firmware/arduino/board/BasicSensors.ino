// BasicSensors - a test sketch for the UKMARSBOT BASIC wall sensor board
// (test/cli/cli_board_builds.sh: boards/ukmarsbot-basic-v1.3.ini with
// robots/ukmarsbot-basic-12.ini), built for the Nano. It reads the sensors
// as older UKMARSBOT firmware does: the one emitter pin (D12) off, A0 (right),
// A1 (front), A2 (left) read dark; the emitter on, 50 us for the detectors to
// settle, the three read lit; the emitter off. Every 20 ms from 0.2 s to
// 1 s it prints "WALLS ms right front left" (lit minus dark, ADC counts).
const uint8_t EMITTER = 12;
const uint8_t RIGHT = A0, FRONT = A1, LEFT = A2;

void setup() {
  Serial.begin(115200);
  pinMode(EMITTER, OUTPUT);
  digitalWrite(EMITTER, 0);
  delay(200);
  for (int i = 0; i < 40; i++) {
    int dark[3], lit[3];
    const uint8_t ch[3] = { RIGHT, FRONT, LEFT };
    for (int k = 0; k < 3; k++) dark[k] = analogRead(ch[k]);
    digitalWrite(EMITTER, 1);
    delayMicroseconds(50);
    for (int k = 0; k < 3; k++) lit[k] = analogRead(ch[k]);
    digitalWrite(EMITTER, 0);
    Serial.print("WALLS ");
    Serial.print(millis());
    for (int k = 0; k < 3; k++) {
      Serial.print(' ');
      Serial.print(lit[k] - dark[k]);
    }
    Serial.println();
    delay(20);
  }
  Serial.println("DONE");
}

void loop() {}
