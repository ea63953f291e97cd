/* simavr_cycles.c - run an AVR image in simavr until it sleeps with
 * interrupts off, print the cycle count. Used by make bench to time the
 * firmware's flood on a 16 MHz ATmega328P without hardware. */
#include <stdio.h>
#include <simavr/sim_avr.h>
#include <simavr/sim_elf.h>

int main(int argc, char **argv)
{
    elf_firmware_t fw = { 0 };
    if (argc != 2 || elf_read_firmware(argv[1], &fw) != 0) {
        fprintf(stderr, "usage: simavr_cycles FILE.elf\n");
        return 2;
    }
    avr_t *avr = avr_make_mcu_by_name("atmega328p");
    if (!avr) return 3;
    avr_init(avr);
    avr->frequency = 16000000;
    avr->log = 0;
    avr_load_firmware(avr, &fw);
    int state = cpu_Running;
    while (state != cpu_Done && state != cpu_Crashed) state = avr_run(avr);
    printf("%llu\n", (unsigned long long)avr->cycle);
    return state == cpu_Done ? 0 : 3;
}
