// MultiTab - a sketch in several files, as the Arduino IDE builds it
// (tools/arduino-build, test/cli/cli_arduino_build.sh): this main tab, a second
// tab (Report.ino) whose functions are used here before they are defined
// (they need the prototypes the build generates), a .cpp/.h pair in the
// folder (twice.cpp) and one in src/util (scale.cpp). scale.cpp also holds
// a 40,000-byte table (two halves) that only unused_mode() != 0 would keep: with -flto
// the linker sees that it is always 0 and drops the table; without -flto
// the table stays and the program no longer fits the Nano's 30,720 bytes.
// Prints on Serial at 115200, once:
//   MULTITAB twice 21 scale 250 table 0
//   REPORT count 3 sum 42
#include "twice.h"
#include "src/util/scale.h"

const int VALUES[] = {10, 12, 20};

void setup() {
  Serial.begin(115200);
  Serial.print(F("MULTITAB twice "));
  Serial.print(twice(10) + 1);
  Serial.print(F(" scale "));
  Serial.print(scale_percent(1000, 25));
  Serial.print(F(" table "));
  Serial.println(unused_mode() ? table_byte(3) : 0);
  report(F("count"), sizeof VALUES / sizeof VALUES[0]);
}

void loop() {}
