/* avrlog.h - simavr's messages and sleep, shared by every board part that
 * makes a core (pil, board): its errors kept for our one-line messages
 * (never printed by simavr itself), and no host sleep when the AVR
 * sleeps: time is cycles, not wall clock. */
#ifndef AVRLOG_H
#define AVRLOG_H

#include <simavr/sim_avr.h>

/* Route simavr's messages to avrlog_last (call before making a core). */
void avrlog_install(void);
/* Forget the last message. */
void avrlog_clear(void);
/* simavr's last error message, "" if none since avrlog_clear. */
const char *avrlog_last(void);
/* ": MESSAGE" if there is one, else "" (to append to an error line). */
const char *avrlog_sep(void);
/* The core's sleep callback: do not sleep the host. */
void avrlog_no_sleep(avr_t *avr, avr_cycle_count_t how_long);

#endif
