// WatchProbe - a test sketch for mmsim --watch (test/cli/cli_watch.sh), built
// for the Nano: every 10 ms by millis() it counts `ticks` up by one, sets
// the variables derived from it (a float, a negative 32-bit, an 8-bit
// signed integer, and a file-scope static 16-bit one), and prints
// "TICK ticks ms" with the millis() it counted at. Also holds what --watch
// must refuse: an array in SRAM and a string in flash (PROGMEM).
#include <avr/pgmspace.h>

volatile uint16_t ticks;      // u16: 10 ms counts since the start
volatile float ratio;         // f32: ticks / 8 (exact in a float)
volatile int32_t offset = -100000L;  // i32: -100000 - 3 * ticks (in .data: set before setup)
volatile int8_t small;        // i8: -(ticks % 100)
static volatile int16_t down;  // i16: -ticks (static: g++ names its symbol _ZL4down)
volatile uint8_t history[4];  // an array: not a number --watch reads
extern const char banner[] PROGMEM = "WATCHPROBE";  // in flash, not SRAM (extern: an unmangled global symbol)
uint32_t next_ms = 10;

void setup() {
  Serial.begin(115200);
  Serial.println((const __FlashStringHelper *)banner);
}

void loop() {
  uint32_t now = millis();
  if (now < next_ms) return;
  next_ms += 10;
  uint16_t n = ticks + 1;
  ticks = n;
  ratio = n / 8.0f;
  offset = -100000L - 3L * n;
  small = -(int8_t)(n % 100);
  down = -(int16_t)n;
  history[n & 3] = (uint8_t)n;
  Serial.print("TICK ");
  Serial.print(n);
  Serial.print(' ');
  Serial.println(now);
}
