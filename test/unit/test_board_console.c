/* test_board_console.c - the board's console (sim/board/board_console.h):
 * it keeps the first BOARD_CONSOLE_MAX - 1 bytes the firmware sends and
 * counts the rest in console_dropped (reported as board.console_dropped);
 * every byte counts in uart_bytes_out. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>

#include "board/board_console.h"

static void test_overflow_counted(void **state)
{
    (void)state;
    static board_stats_t st;
    board_console_t c;
    char err[100];
    assert_int_equal(board_console_init(&c, &st, err, sizeof err), 0);
    const size_t keep = BOARD_CONSOLE_MAX - 1, extra = 37;
    for (size_t i = 0; i < keep + extra; i++) board_console_byte(&c, (uint8_t)('a' + i % 26));
    assert_int_equal(c.con.len, keep);
    assert_int_equal(strlen(c.con.text), keep);
    assert_int_equal(st.console_dropped, extra);
    assert_int_equal(st.uart_bytes_out, keep + extra);
    board_console_free(&c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_overflow_counted),
    };
    return cmocka_run_group_tests_name("board_console", tests, NULL, NULL);
}
