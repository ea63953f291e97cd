/* board_console.h - the UART part: every byte the firmware sends on UART0
 * kept as the console (and echoed live with --verbose). Typed input goes
 * through the AVR host's queue (avrhost.h). */
#ifndef BOARD_CONSOLE_H
#define BOARD_CONSOLE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "board.h"
#include "io/console.h"

typedef struct {
    console_t con;                /* kept text, live tail, --end-on, echo */
    board_stats_t *st;            /* uart_bytes_out, console_dropped */
} board_console_t;

/* 0, or -1 with "out of memory" in err. */
int board_console_init(board_console_t *c, board_stats_t *st, char *err, size_t errn);
void board_console_free(board_console_t *c);
/* One byte from the firmware (avrhost_sink_fn, ctx = the console). */
void board_console_byte(void *ctx, uint8_t byte);

#endif
