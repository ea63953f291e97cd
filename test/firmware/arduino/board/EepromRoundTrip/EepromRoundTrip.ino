// EepromRoundTrip - the core's EEPROM library across power cycles
// (tools/arduino-build adds the library for the #include below;
// test/cli/cli_arduino_build.sh runs it twice with the same `mmsim --eeprom FILE`).
// At power-on it reads its record at address 0: a marker, a boot count and a
// value. A blank chip (all 0xFF: no marker) starts the record at count 0,
// value 100. It prints on Serial at 115200
//   EEPROM boot N value V
// then writes the record back with the count one up and the value doubled,
// and prints
//   EEPROM saved N+1
#include <EEPROM.h>

const uint16_t MARKER = 0x4D4D;  // "MM": the record was written by this sketch

struct Record {
  uint16_t marker;
  uint16_t boots;  // power-ons before this one
  long value;      // 100 at the first power-on, doubled at each
};

void setup() {
  Serial.begin(115200);
  Record r;
  EEPROM.get(0, r);
  if (r.marker != MARKER) r = Record{MARKER, 0, 100};
  Serial.print(F("EEPROM boot "));
  Serial.print(r.boots);
  Serial.print(F(" value "));
  Serial.println(r.value);
  r.boots++;
  r.value *= 2;
  EEPROM.put(0, r);
  Serial.print(F("EEPROM saved "));
  Serial.println(r.boots);
}

void loop() {}
