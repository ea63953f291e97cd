/* board_console.c - the UART part (board_console.h). */
#include "board_console.h"

#include <stdlib.h>

int board_console_init(board_console_t *c, board_stats_t *st, char *err, size_t errn)
{
    c->st = st;
    c->len = 0;
    c->echo = NULL;
    c->text = malloc(BOARD_CONSOLE_MAX);
    if (!c->text) return snprintf(err, errn, "out of memory"), -1;
    c->text[0] = '\0';
    return 0;
}

void board_console_byte(void *ctx, uint8_t byte)
{
    board_console_t *c = ctx;
    char ch = (char)byte;
    c->st->uart_bytes_out++;
    if (c->len + 1 < BOARD_CONSOLE_MAX) {
        c->text[c->len++] = ch;
        c->text[c->len] = '\0';
    } else c->st->console_dropped++;
    if (c->echo) {
        fputc(ch, c->echo);
        if (ch == '\n') fflush(c->echo);
    }
}
