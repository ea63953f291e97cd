// UartEcho - each line received on UART0 (to '\n', a '\r' dropped) printed
// back as `ECHO text`. ECHO_BAUD: 115200 unless the build sets it.
#ifndef ECHO_BAUD
#define ECHO_BAUD 115200
#endif

static char line[64];
static uint8_t len;

void setup() {
  Serial.begin(ECHO_BAUD);
  Serial.print(F("UARTECHO "));
  Serial.println((long)ECHO_BAUD);
}

void loop() {
  while (Serial.available()) {
    char c = Serial.read();
    if (c == '\r') continue;
    if (c == '\n') {
      line[len] = 0;
      Serial.print(F("ECHO "));
      Serial.println(line);
      len = 0;
    } else if (len < sizeof line - 1) {
      line[len++] = c;
    }
  }
}
