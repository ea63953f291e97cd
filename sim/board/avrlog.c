/* avrlog.c - simavr's messages and sleep (see avrlog.h). */
#include "avrlog.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static char last_log[200]; /* simavr's last error message, for ours */

static void quiet_logger(avr_t *avr, const int level, const char *fmt, va_list ap)
{
    (void)avr;
    if (level > LOG_ERROR) return;
    vsnprintf(last_log, sizeof last_log, fmt, ap);
    size_t n = strlen(last_log);
    while (n > 0 && (last_log[n - 1] == '\n' || last_log[n - 1] == '\r')) last_log[--n] = '\0';
}

void avrlog_install(void) { avr_global_logger_set(quiet_logger); }
void avrlog_clear(void) { last_log[0] = '\0'; }
const char *avrlog_last(void) { return last_log; }
const char *avrlog_sep(void) { return last_log[0] ? ": " : ""; }
void avrlog_no_sleep(avr_t *avr, avr_cycle_count_t how_long) { (void)avr, (void)how_long; }
