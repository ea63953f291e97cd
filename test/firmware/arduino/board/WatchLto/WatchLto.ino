// WatchLto - a test sketch for mmsim --watch on an LTO build (test/cli/cli_watch.sh):
// two files each hold a file-scope static named s_robot_angle (angle.cpp's in
// SRAM, counting up by 0.5 every 10 ms; other.cpp's a constant in flash) and
// one named s_count in SRAM, so -flto renames each symbol NAME.lto_priv.N;
// DWARF keeps the source names. Prints "ANGLE a" with each step.
#include "angle.h"

void setup() { Serial.begin(115200); }

void loop() {
  angle_step();
  Serial.print("ANGLE ");
  Serial.println(angle_now() + other_offset());
  delay(10);
}
