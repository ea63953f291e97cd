/* test_console.c - a firmware's serial output as a run keeps it
 * (sim/io/console.h): the kept part, the live tail a pty reads, and the
 * --end-on text found past the kept part and across chunk boundaries. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <string.h>

#include "io/console.h"

static void feed(console_t *c, const char *s)
{
    while (*s) console_byte(c, (uint8_t)*s++);
}

/* The first CONSOLE_KEEP - 1 bytes kept, the rest counted; --end-on's text found 2 MiB in. */
static void test_text_found_past_the_kept_part(void **state)
{
    (void)state;
    console_t c;
    char err[64];
    assert_int_equal(console_init(&c, err, sizeof err), 0);
    console_look_for(&c, "Data logging off");
    for (size_t i = 0; i < 2u * CONSOLE_KEEP; i++) console_byte(&c, (uint8_t)('a' + i % 26));
    assert_false(console_seen(&c));
    feed(&c, "Data logging o");
    assert_false(console_seen(&c));
    feed(&c, "ff\r\n");
    assert_true(console_seen(&c));
    assert_int_equal(c.len, CONSOLE_KEEP - 1);
    assert_int_equal(c.dropped, CONSOLE_KEEP + 1 + 18);
    assert_int_equal(c.total, 2u * CONSOLE_KEEP + 18);
    console_free(&c);
}

/* A text that never appears whole (its halves far apart) is not seen. */
static void test_text_must_be_contiguous(void **state)
{
    (void)state;
    console_t c;
    char err[64];
    assert_int_equal(console_init(&c, err, sizeof err), 0);
    console_look_for(&c, "done");
    feed(&c, "do");
    feed(&c, "x");
    feed(&c, "ne");
    assert_false(console_seen(&c));
    feed(&c, "ddone");
    assert_true(console_seen(&c));
    console_free(&c);
}

/* A reader gets the kept part whole, then the tail; what it fell behind by past the kept part is counted lost. */
static void test_reader_kept_then_tail(void **state)
{
    (void)state;
    console_t c;
    char err[64], buf[256];
    assert_int_equal(console_init(&c, err, sizeof err), 0);
    uint64_t pos = 0, lost = 0;
    feed(&c, "hello");
    assert_int_equal(console_read(&c, &pos, buf, sizeof buf, &lost), 5);
    assert_memory_equal(buf, "hello", 5);
    assert_int_equal(console_read(&c, &pos, buf, sizeof buf, &lost), 0);
    size_t past = CONSOLE_KEEP + 2u * CONSOLE_TAIL;
    for (size_t i = 5; i < past; i++) console_byte(&c, (uint8_t)(i % 251));
    pos = CONSOLE_KEEP - 3; /* the kept part's last two bytes, then a jump to the tail */
    size_t k = console_read(&c, &pos, buf, sizeof buf, &lost);
    assert_int_equal(k, sizeof buf);
    assert_int_equal((uint8_t)buf[0], (CONSOLE_KEEP - 3) % 251);
    assert_int_equal((uint8_t)buf[1], (CONSOLE_KEEP - 2) % 251);
    assert_int_equal((uint8_t)buf[2], (past - CONSOLE_TAIL) % 251);
    assert_int_equal(lost, past - CONSOLE_TAIL - (CONSOLE_KEEP - 1));
    assert_int_equal(pos, past - CONSOLE_TAIL + sizeof buf - 2);
    console_free(&c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_text_found_past_the_kept_part),
        cmocka_unit_test(test_text_must_be_contiguous),
        cmocka_unit_test(test_reader_kept_then_tail),
    };
    return cmocka_run_group_tests_name("console", tests, NULL, NULL);
}
