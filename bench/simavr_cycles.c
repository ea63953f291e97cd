/* simavr_cycles.c - run an AVR image in simavr until it sleeps with
 * interrupts off, print the cycle count (last line). Used by make bench to
 * time firmware code on a 16 MHz ATmega328P without hardware.
 *
 * Marks: the image may write 2n (start) and 2n+1 (end) to GPIOR0 around a
 * call; simavr's cycle counter is read at each write and, per mark n, the
 * count, mean and max of the intervals are printed first, one line each:
 * "mark N: COUNT calls, mean MEAN, max MAX cycles". */
#include <stdio.h>
#include <simavr/sim_avr.h>
#include <simavr/sim_elf.h>
#include <simavr/sim_io.h>

#define GPIOR0_ADDR 0x3E /* data-space address of GPIOR0 on the ATmega328P */
#define MARKS 128

static struct {
    avr_cycle_count_t start, total, max;
    unsigned long count;
} marks[MARKS];

static void on_mark(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param)
{
    (void)addr;
    (void)param;
    unsigned n = v >> 1;
    if (!(v & 1u)) {
        marks[n].start = avr->cycle;
        return;
    }
    avr_cycle_count_t d = avr->cycle - marks[n].start;
    marks[n].total += d;
    marks[n].count++;
    if (d > marks[n].max) marks[n].max = d;
}

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
    avr_register_io_write(avr, GPIOR0_ADDR, on_mark, NULL);
    int state = cpu_Running;
    while (state != cpu_Done && state != cpu_Crashed) state = avr_run(avr);
    for (unsigned n = 0; n < MARKS; n++)
        if (marks[n].count)
            printf("mark %u: %lu calls, mean %llu, max %llu cycles\n", n, marks[n].count,
                   (unsigned long long)(marks[n].total / marks[n].count), (unsigned long long)marks[n].max);
    printf("%llu\n", (unsigned long long)avr->cycle);
    return state == cpu_Done ? 0 : 3;
}
