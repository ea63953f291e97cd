/* test_escape.c - text from outside made safe to print (sim/io/escape.h):
 * control bytes, invalid and steering UTF-8 as \xNN, printable UTF-8 kept,
 * output cut only between whole characters; and the MCU's LOG lines as
 * the link prints them (sim/link: "mcu: TEXT", escaped). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <fcntl.h>
#include <unistd.h>
#include <cmocka.h>

#include "io/escape.h"
#include "link/link.h"
#include "wire.h"

static const char *esc(const char *in, size_t n)
{
    static char out[IO_ESCAPE_MAX(256)];
    io_escape(out, sizeof out, in, n);
    return out;
}
#define ESC(s) esc(s, sizeof(s) - 1)

static void test_bytes(void **state)
{
    (void)state;
    assert_string_equal(ESC("plain text, 100% ok ~"), "plain text, 100% ok ~");
    assert_string_equal(ESC("a\nb"), "a\\x0Ab");
    assert_string_equal(ESC("\rmmsim: forged"), "\\x0Dmmsim: forged");
    assert_string_equal(ESC("\033[2J\033]0;title\007"), "\\x1B[2J\\x1B]0;title\\x07");
    assert_string_equal(ESC("tab\there"), "tab\\x09here");
    assert_string_equal(ESC("nul\0in"), "nul\\x00in"); /* the length counts, not the first NUL */
    assert_string_equal(ESC("del\177"), "del\\x7F");
    assert_string_equal(ESC("back\\slash"), "back\\\\slash"); /* so \x41 in the text is not read as an escape */
}

static void test_utf8(void **state)
{
    (void)state;
    assert_string_equal(ESC("caf\xC3\xA9 \xE2\x98\x83 \xF0\x9F\x90\xAD"), "caf\xC3\xA9 \xE2\x98\x83 \xF0\x9F\x90\xAD");
    assert_string_equal(ESC("\xC3"), "\\xC3");                   /* cut short */
    assert_string_equal(ESC("\xC3(x"), "\\xC3(x");               /* a bad continuation */
    assert_string_equal(ESC("\xC0\xAF"), "\\xC0\\xAF");          /* overlong '/' */
    assert_string_equal(ESC("\xE0\x80\xAF"), "\\xE0\\x80\\xAF"); /* overlong */
    assert_string_equal(ESC("\xED\xA0\x80"), "\\xED\\xA0\\x80"); /* a surrogate */
    assert_string_equal(ESC("\xF4\x90\x80\x80"), "\\xF4\\x90\\x80\\x80"); /* above U+10FFFF */
    assert_string_equal(ESC("\xFF\xFE"), "\\xFF\\xFE");
    /* valid, but they steer: C1 CSI, RTL override, line separator, BOM */
    assert_string_equal(ESC("\xC2\x9B" "31m"), "\\xC2\\x9B31m");
    assert_string_equal(ESC("\xE2\x80\xAE" "txt"), "\\xE2\\x80\\xAEtxt");
    assert_string_equal(ESC("a\xE2\x80\xA8" "b"), "a\\xE2\\x80\\xA8b");
    assert_string_equal(ESC("\xEF\xBB\xBF" "x"), "\\xEF\\xBB\\xBFx");
}

static void test_room(void **state)
{
    (void)state;
    char out[8];
    assert_int_equal(io_escape(out, sizeof out, "abc\ndef", 7), 7); /* "abc\x0A": no room for more */
    assert_string_equal(out, "abc\\x0A");
    assert_int_equal(io_escape(out, sizeof out, "ab\ncd", 5), 7);
    assert_string_equal(out, "ab\\x0Ac");
    assert_int_equal(io_escape(out, 5, "ab\xE2\x98\x83", 5), 2); /* the snowman does not fit whole: left out */
    assert_string_equal(out, "ab");
    assert_int_equal(io_escape(out, 1, "abc", 3), 0);
    assert_string_equal(out, "");
    char big[IO_ESCAPE_MAX(4)];
    assert_int_equal(io_escape(big, sizeof big, "\x01\x02\x03\x04", 4), 16); /* the worst case fits */
}

/* An MCU's LOG with control bytes, through the link: one line, escaped. */
static void test_mcu_log(void **state)
{
    (void)state;
    int sv[2];
    assert_int_equal(socketpair(AF_UNIX, SOCK_STREAM, 0, sv), 0);
    fcntl(sv[0], F_SETFL, O_NONBLOCK);
    char *text = NULL;
    size_t len = 0;
    FILE *report = open_memstream(&text, &len);
    assert_non_null(report);
    static link_t lk;
    link_opts_t o = { NULL, 0, 1000000, LINK_FRAMED, 0.1 };
    link_open_fd(&lk, sv[0], "socketpair", &o, 0.001, 1200, 35832, report);
    static const char forged[] = "hi\r\nmmsim: link socketpair: forged\033[2K";
    wire_msg_t m = { .type = WIRE_LOG, .u.log = { sizeof forged - 1, forged } };
    uint8_t b[WIRE_FRAME_MAX];
    size_t n = wire_encode(&m, b, sizeof b);
    assert_true(n > 0);
    assert_int_equal(write(sv[1], b, n), (ssize_t)n);
    link_io_t io;
    int16_t mo[2];
    memset(&io, 0, sizeof io);
    for (int s = 0; s < 5; s++) {
        io.t_us = (uint32_t)(s + 1) * 1000u;
        link_step_io(&lk, &io, mo);
    }
    link_close(&lk);
    close(sv[1]);
    fclose(report);
    assert_non_null(strstr(text, "mcu: hi\\x0D\\x0Ammsim: link socketpair: forged\\x1B[2K\n"));
    assert_null(strstr(text, "\nmmsim: link socketpair: forged"));
    assert_null(strchr(text, '\033'));
    free(text);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bytes),
        cmocka_unit_test(test_utf8),
        cmocka_unit_test(test_room),
        cmocka_unit_test(test_mcu_log),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
