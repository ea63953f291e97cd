/* board_console.c - the UART part (board_console.h). */
#include "board_console.h"

int board_console_init(board_console_t *c, board_stats_t *st, char *err, size_t errn)
{
    c->st = st;
    return console_init(&c->con, err, errn);
}

void board_console_free(board_console_t *c) { console_free(&c->con); }

void board_console_byte(void *ctx, uint8_t byte)
{
    board_console_t *c = ctx;
    c->st->uart_bytes_out++;
    console_byte(&c->con, byte);
    c->st->console_dropped = c->con.dropped;
}
