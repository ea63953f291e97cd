// NoinitReset - a test sketch for the board emulation (test/unit/test_board.c):
// counts its boots in .noinit RAM (power-on SRAM is zero, a reset keeps
// it), prints "BOOT n" at each start, then the switch ladder (A6) every
// 50 ms as "SW a6".
uint16_t boots __attribute__((section(".noinit")));
uint16_t magic __attribute__((section(".noinit")));

void setup() {
  Serial.begin(115200);
  if (magic != 0xBEEF) {
    magic = 0xBEEF;
    boots = 0;
  }
  boots++;
  Serial.print("BOOT ");
  Serial.println(boots);
}

void loop() {
  delay(50);
  Serial.print("SW ");
  Serial.println(analogRead(6));
}
