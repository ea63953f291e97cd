/* ukb_console.h - UART0 at 115200 baud (the Nano's USB serial): log lines
 * out through a transmit ring, single characters in. */
#ifndef UKB_CONSOLE_H
#define UKB_CONSOLE_H

#include <stdint.h>

#define UKB_CONSOLE_BAUD 115200UL /* baud, 8N1 */

void ukb_console_init(void);
/* the next received character, or -1 if none */
int ukb_console_getc(void);
/* a line from a format in flash (PSTR) with printf arguments; waits for
 * room in the ring (main loop only, never from the systick) */
void ukb_console_printf_P(const char *fmt_in_flash, ...);
/* lines hal_log dropped because the ring was full */
uint16_t ukb_console_dropped(void);

#endif
