// Persist - what survives a reset. At each boot:
//   BOOT n   a .noinit counter as found (the C runtime zeroes .bss, not
//            .noinit: 0 at power-on, where SRAM is zero, then one more
//            after each reset, which keeps SRAM), then incremented
//   EE n     a 16-bit counter at EEPROM address 0 (avr/eeprom.h; erased
//            0xFFFF read as 0) incremented, written, and read back
//   MCUSR x  the reset flags (PORF 1, EXTRF 2, BORF 4, WDRF 8), as found
#include <avr/eeprom.h>
#include <avr/io.h>

static uint16_t boot_count __attribute__((section(".noinit")));
static uint8_t mcusr_at_boot __attribute__((section(".noinit")));

// MCUSR saved and cleared before the core's init (as optiboot-less sketches do)
void save_mcusr(void) __attribute__((naked, used, section(".init3")));
void save_mcusr(void) {
  mcusr_at_boot = MCUSR;
  MCUSR = 0;
}

void setup() {
  uint16_t found = boot_count;
  boot_count = found + 1;
  Serial.begin(115200);
  Serial.println(F("PERSIST"));
  Serial.print(F("BOOT "));
  Serial.println(found);
  uint16_t *const addr = (uint16_t *)0;
  uint16_t ee = eeprom_read_word(addr);
  if (ee == 0xFFFF) ee = 0;
  eeprom_write_word(addr, ee + 1);
  uint16_t back = eeprom_read_word(addr);
  Serial.print(F("EE "));
  Serial.println(back);
  Serial.print(F("MCUSR "));
  Serial.println(mcusr_at_boot);
}

void loop() {}
