/* test_image.c - firmware images checked before simavr reads them
 * (sim/board/image.h through avrhost_read/avrhost_put, as --board and --avr
 * call them): a corpus of crafted ELF and Intel HEX files written to a
 * temporary directory from a real small image (the MotorPwm sketch,
 * build/clients/board/MotorPwm.elf, `make board-sketches`; skipped without
 * it), each giving its one error line and never a signal (the test is
 * built with ASan and UBSan): ELF header fields, tables and sections
 * outside the file, section and symbol name offsets, .mmcu tags (a wrong
 * MCU, a 65-character name, clocks, a VCD trace that must write nothing),
 * code, variables and EEPROM beyond the MCU's; HEX checksums, garbage,
 * lengths, record types, a truncated end, wrapping and oversize addresses;
 * and images with random bytes in their headers, tables and names.
 * The good image, as ELF and as HEX, loads and runs with the same flash. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <simavr/sim_avr.h>

#include "board/avrhost.h"

#define BASE_IMAGE "build/clients/board/MotorPwm.elf"
#define ERRN 400
#define ROOM_BYTES (64u << 10) /* room to grow a crafted image by */
#define BOARD_MCU "atmega328p"
#define F_CPU_HZ 16000000u
#define RUN_CYCLES 20000u /* AVR cycles a loaded image runs */
#define FUZZ_IMAGES 300   /* images with random bytes in their headers, tables and names */
#define FUZZ_BYTES 3      /* random bytes written into each (about half the images then load) */

static char dir[] = "/tmp/test_image_XXXXXX";
static uint8_t *base;  /* the real image */
static size_t base_n;  /* its bytes */
static uint8_t *buf;   /* the image being crafted (base_n + ROOM_BYTES) */
static uint64_t run_cycles = RUN_CYCLES; /* AVR cycles load runs a loaded image (0: none) */
static size_t buf_n;

static uint32_t rd16(const uint8_t *p) { return (uint32_t)p[0] | (uint32_t)p[1] << 8; }
static uint32_t rd32(const uint8_t *p) { return rd16(p) | rd16(p + 2) << 16; }
static void wr16(uint8_t *p, uint32_t v) { p[0] = (uint8_t)v, p[1] = (uint8_t)(v >> 8); }
static void wr32(uint8_t *p, uint32_t v) { wr16(p, v), wr16(p + 2, v >> 16); }

static uint8_t *shdr(uint32_t i) { return buf + rd32(buf + 32) + (size_t)i * 40u; }
static uint32_t nsec(void) { return rd16(buf + 48); }
static char *sec_name(uint32_t i) { return (char *)buf + rd32(shdr(rd16(buf + 50)) + 16) + rd32(shdr(i)); }

static uint32_t find(const char *name)
{
    for (uint32_t i = 0; i < nsec(); i++)
        if (!strcmp(sec_name(i), name)) return i;
    fail_msg("%s has no %s section", BASE_IMAGE, name);
    return 0;
}

static int setup(void **state)
{
    (void)state;
    FILE *f = fopen(BASE_IMAGE, "rb");
    if (!f) return 0;
    fseek(f, 0, SEEK_END);
    base_n = (size_t)ftell(f);
    rewind(f);
    base = malloc(base_n);
    buf = malloc(base_n + ROOM_BYTES);
    if (!base || !buf || fread(base, 1, base_n, f) != base_n) return -1;
    fclose(f);
    return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    char cmd[100];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    if (base && system(cmd) != 0) return -1;
    free(base);
    free(buf);
    return 0;
}

/* a fresh copy of the real image to craft */
static void fresh(void)
{
    if (!base) skip();
    memcpy(buf, base, base_n);
    memset(buf + base_n, 0, ROOM_BYTES);
    buf_n = base_n;
}

static const char *put(const char *name, const void *bytes, size_t n)
{
    static char path[200];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(bytes, 1, n, f), n);
    fclose(f);
    return path;
}

/* path loaded as --board (board_mcu set: the board's MCU and clock) or --avr
 * (NULL: the image's MCU or the default, f_cpu or the image's clock) calls
 * it, then run for some cycles: 0, or -1 with err */
static int load(const char *path, const char *board_mcu, uint32_t f_cpu, char *err, avrhost_t *host_out)
{
    avrhost_image_t img;
    static avrhost_t own;
    avrhost_t *hp = host_out ? host_out : &own, h;
    memset(&h, 0, sizeof h);
    err[0] = '\0';
    if (avrhost_read(&img, path, board_mcu != NULL, board_mcu, board_mcu ? "ukmarsbot" : NULL, err, ERRN) != 0) return -1;
    const char *mcu = board_mcu ? board_mcu : img.mcu[0] ? img.mcu : AVRHOST_DEFAULT_MCU;
    uint32_t f = board_mcu ? F_CPU_HZ : f_cpu ? f_cpu : img.f_cpu ? img.f_cpu : F_CPU_HZ;
    if (avrhost_make(&h, mcu, path, err, ERRN) != 0) {
        if (img.hex) image_hex_free(&img.bytes);
        return -1;
    }
    int rc = avrhost_put(&h, &img, path, mcu, f, 0.001, err, ERRN);
    if (rc == 0 && run_cycles) rc = avrhost_run_to(&h, h.avr->cycle + run_cycles, err, ERRN);
    *hp = h; /* the caller's to look into and close (avrhost_close), or closed here */
    if (!host_out) avrhost_close(hp);
    return rc;
}

/* the crafted image as file name refused as board (1) or --avr (0) would, with want in its one line */
static void refused_as(const char *name, int board, const char *want)
{
    char err[ERRN];
    const char *path = put(name, buf, buf_n);
    int rc = load(path, board ? BOARD_MCU : NULL, 0, err, NULL);
    if (rc != -1 || !strstr(err, want) || strchr(err, '\n') || strncmp(err, path, strlen(path)) != 0)
        fail_msg("%s: rc %d, '%s' (want '%s')", name, rc, err, want);
}

static void refused(const char *name, const char *want)
{
    refused_as(name, 1, want);
    refused_as(name, 0, want);
}

/* ---- ELF ---- */

static void test_elf_header(void **state)
{
    (void)state;
    fresh(), buf[4] = 2, refused("class64.elf", "a 64-bit ELF");
    fresh(), buf[5] = 2, refused("be.elf", "a big-endian ELF");
    fresh(), wr16(buf + 18, 82), refused("machine.elf", "an ELF for machine 82, not an AVR (83)");
    fresh(), buf_n = 40, refused("short.elf", "not an AVR ELF image");
    fresh(), wr32(buf + 28, (uint32_t)base_n - 8u), refused("phoff.elf", "its program header table");
    fresh(), wr16(buf + 42, 8), refused("phentsize.elf", "its program header table");
    fresh(), wr32(buf + 32, (uint32_t)base_n - 10u), refused("shoff.elf", "its section header table");
    fresh(), wr32(buf + 32, 0xFFFFFFF0u), refused("shoff-wrap.elf", "its section header table");
    fresh(), wr16(buf + 48, 0xFFFF), refused("shnum.elf", "its section header table");
    fresh(), wr16(buf + 46, 20), refused("shentsize.elf", "its section header table");
    fresh(), wr16(buf + 50, (uint16_t)nsec()), refused("shstrndx.elf", "its section name table index");
    fresh(), wr16(buf + 50, (uint16_t)find(".text")), refused("shstrndx-text.elf", "is not a string table");
}

static void test_elf_sections(void **state)
{
    (void)state;
    fresh(), wr32(shdr(find(".text")), 0xFFFF), refused("name.elf", "name (at 0xffff) is not within the section name table");
    fresh(), wr32(shdr(find(".data")), 0x7FFFFFFF), refused("name2.elf", "is not within the section name table");
    uint32_t t;
    fresh(), t = find(".text"), wr32(shdr(t) + 16, 0xFFFFFFF0u), wr32(shdr(t) + 20, 0x20), refused("off-wrap.elf", "is not within the file");
    fresh(), t = find(".text"), wr32(shdr(t) + 20, (uint32_t)base_n), refused("size.elf", "is not within the file");
    fresh(), t = find(".data"), wr32(shdr(t) + 20, 0xFFFFFFFFu), refused("size-max.elf", "is not within the file");
    fresh(), t = find(".text"), wr32(shdr(t) + 4, 8), refused("nobits.elf", "section .text has no bytes in the file");
    fresh(), t = find(".data"), wr32(shdr(t) + 4, 4), refused("rela-data.elf", "section .data is of type 4, not program bytes");
    fresh(), t = find(".bss"), wr32(shdr(t) + 4, 11), refused("dynsym-bss.elf", "section .bss is of type 11, not NOBITS");
    /* libelf inflates a compressed section: simavr then finds no section names */
    fresh(), t = rd16(buf + 50), wr32(shdr(t) + 8, 0x4900), refused("compressed.elf", "is compressed (SHF_COMPRESSED)");
    fresh(), t = find(".symtab"), wr32(shdr(t) + 36, 0), refused("entsize.elf", "entries of 0 bytes");
    fresh(), t = find(".symtab"), wr32(shdr(t) + 24, find(".text")), refused("symlink.elf", "not a string table");
    fresh(), t = find(".symtab"), wr32(buf + rd32(shdr(t) + 16) + 16, 0xFFFFFF), refused("symname.elf", "symbol 1's name");
    /* .comment renamed .lock: simavr reads a .lock only beside a .fuse */
    fresh(), strcpy(sec_name(find(".comment")), ".lock"), refused("lock.elf", "a .lock section without a .fuse");
    fresh(), t = find(".comment"), strcpy(sec_name(t), ".fuse"), refused("fuse.elf", "section .fuse has 17 bytes");
}

/* .debug_info renamed .mmcu, holding the n bytes of tags */
static void mmcu(const void *tags, size_t n)
{
    fresh();
    uint32_t t = find(".debug_info");
    assert_true(n <= rd32(shdr(t) + 20));
    strcpy(sec_name(t), ".mmcu");
    memcpy(buf + rd32(shdr(t) + 16), tags, n);
    wr32(shdr(t) + 20, (uint32_t)n);
}

/* a .mmcu with an MCU name tag of name and a clock tag of hz (0: none) */
static void mmcu_name_clock(const char *name, uint32_t hz)
{
    uint8_t t[300];
    size_t n = 0, len = strlen(name) + 1;
    t[n++] = 1, t[n++] = (uint8_t)len;
    memcpy(t + n, name, len), n += len;
    if (hz) t[n++] = 2, t[n++] = 4, wr32(t + n, hz), n += 4;
    t[n++] = 0, t[n++] = 0;
    mmcu(t, n);
}

static void test_mmcu(void **state)
{
    (void)state;
    char err[ERRN], long_name[66];
    memset(long_name, 'm', 65), long_name[65] = '\0';
    mmcu_name_clock("atmega2560", 0), refused_as("m2560.elf", 1, "built for the atmega2560; the board ukmarsbot has an atmega328p");
    mmcu_name_clock("atmega32", 0), refused_as("m32.elf", 1, "built for the atmega32;");
    mmcu_name_clock(long_name, 0), refused("name65.elf", "its MCU name is 65 characters (at most 63)");
    mmcu_name_clock(BOARD_MCU, 4000000000u), refused_as("4ghz.elf", 1, "built for a 4000000000 Hz clock (.mmcu), run at 16000000 Hz");
    refused_as("4ghz.elf", 0, "a clock of 4000000000 Hz (an AVR runs at 1 to 32 MHz)");
    mmcu_name_clock(BOARD_MCU, 1), refused_as("1hz.elf", 1, "built for a 1 Hz clock");
    refused_as("1hz.elf", 0, "a clock of 1 Hz");
    mmcu_name_clock(BOARD_MCU, 8000000u), refused_as("8mhz.elf", 1, "built for a 8000000 Hz clock");
    assert_int_equal(load(put("8mhz-avr.elf", buf, buf_n), NULL, 0, err, NULL), 0); /* --avr: the image's clock */
    assert_int_equal(load(put("8mhz-avr.elf", buf, buf_n), NULL, 12000000u, err, NULL), -1); /* --f-cpu 12 MHz */
    assert_non_null(strstr(err, "built for a 8000000 Hz clock (.mmcu), run at 12000000 Hz"));
    mmcu_name_clock(BOARD_MCU, F_CPU_HZ), assert_int_equal(load(put("ok.elf", buf, buf_n), BOARD_MCU, 0, err, NULL), 0);
    mmcu("\x01\x04" "atme", 6), refused("unended.elf", "its MCU name does not end within its tag");
    mmcu_name_clock("atm\nega", 0), refused("newline.elf", "its MCU name has a byte 0x0A");
    mmcu("\x01\xc8" "atmega328p", 12), refused("past.elf", "the tag at byte 0 runs past its section (12 bytes)");
    mmcu("\x00\x00\x00", 3), refused("odd.elf", "the tag at byte 2 runs past its section");
    mmcu("\x02\x02\x00\x24", 4), refused("short-clock.elf", "tag 2 has 2 bytes (simavr reads 4)");
    uint8_t traces[33 * 6];
    for (int i = 0; i < 33; i++) memcpy(traces + 6 * i, "\x0e\x04\xff\x25\x00\x00", 6);
    mmcu(traces, sizeof traces), refused("traces.elf", "more than 32 trace tags");
    mmcu("\x0f\x05\x42\x05\x00" "PB", 7), refused("portpin.elf", "its trace name does not end within its tag");
    char tag[300];
    tag[0] = 12, tag[1] = 201, memset(tag + 2, 'v', 200), tag[202] = '\0';
    mmcu(tag, 203), refused("tracename.elf", "its trace file name is 200 characters (at most 127)");
    fresh(), wr32(buf + 36, (rd32(buf + 36) & ~0x7Fu) | 6u), refused("avr6.elf", "built for another MCU (AVR architecture avr6;");
}

/* a VCD trace, its period and a command and console register in .mmcu: nothing is written, no command taken */
static void test_mmcu_trace_never_acts(void **state)
{
    (void)state;
    char vcd[200], err[ERRN];
    uint8_t t[300];
    size_t n = 0;
    snprintf(vcd, sizeof vcd, "%s/trace.vcd", dir);
    t[n++] = 12, t[n++] = (uint8_t)(strlen(vcd) + 1), memcpy(t + n, vcd, strlen(vcd) + 1), n += strlen(vcd) + 1;
    memcpy(t + n, "\x0d\x04\xe8\x03\x00\x00", 6), n += 6;                 /* VCD period 1000 */
    memcpy(t + n, "\x0e\x07\xff\x25\x00" "PB\0", 9), n += 9;             /* a trace of PORTB */
    memcpy(t + n, "\x0a\x02\x31\x00" "\x0b\x02\x32\x00", 8), n += 8;     /* command and console registers */
    if (base) mmcu(t, n);
    else skip();
    static avrhost_t host;
    assert_int_equal(load(put("vcd.elf", buf, buf_n), BOARD_MCU, 0, err, &host), 0);
    assert_null(host.avr->vcd);
    assert_int_equal(access(vcd, F_OK), -1);
    avrhost_close(&host);
    assert_int_equal(access(vcd, F_OK), -1);
}

static void test_sizes(void **state)
{
    (void)state;
    uint32_t t;
    fresh(), t = find(".text"), wr32(shdr(t) + 16, 0), wr32(shdr(t) + 20, 40u << 10), buf_n = base_n + ROOM_BYTES;
    refused("40k.elf", "bytes of code: larger than the atmega328p's flash (32768 bytes)");
    fresh(), wr32(shdr(find(".bss")) + 20, 3000), refused("bss.elf", "bytes of variables (.data and .bss): more than the atmega328p's SRAM (2048 bytes)");
    fresh(), t = find(".comment"), strcpy(sec_name(t), ".eeprom"), wr32(shdr(t) + 16, 0), wr32(shdr(t) + 20, 2000);
    refused("eeprom.elf", "2000 bytes of .eeprom: more than the atmega328p's EEPROM (1024 bytes)");
}

/* ---- Intel HEX ---- */

/* one record into out (appended): its checksum right */
static void rec(char *out, unsigned type, unsigned addr, const uint8_t *data, unsigned len)
{
    unsigned sum = len + (addr >> 8) + (addr & 0xFFu) + type;
    char *p = out + strlen(out);
    p += sprintf(p, ":%02X%04X%02X", len, addr & 0xFFFFu, type);
    for (unsigned i = 0; i < len; i++) p += sprintf(p, "%02X", data[i]), sum += data[i];
    sprintf(p, "%02X\n", (0x100u - (sum & 0xFFu)) & 0xFFu);
}

static char *hex;       /* the HEX text being crafted */
static uint8_t *flash;  /* the real image's flash bytes (.text then .data, as simavr loads them) */
static size_t flash_n;

/* the real image's flash as HEX records of 16 bytes (without its end record if !end) */
static void hex_of_image(int end)
{
    fresh();
    uint32_t t = find(".text"), d = find(".data");
    size_t nt = rd32(shdr(t) + 20), nd = rd32(shdr(d) + 20);
    flash_n = nt + nd;
    flash = realloc(flash, flash_n);
    memcpy(flash, buf + rd32(shdr(t) + 16), nt);
    memcpy(flash + nt, buf + rd32(shdr(d) + 16), nd);
    hex = realloc(hex, flash_n * 3 + 1000);
    hex[0] = '\0';
    for (size_t a = 0; a < flash_n; a += 16) rec(hex, 0, (unsigned)a, flash + a, flash_n - a < 16 ? (unsigned)(flash_n - a) : 16u);
    if (end) rec(hex, 1, 0, NULL, 0);
}

/* hex refused on the board with "PATH:LINE: want" (line 0: "PATH: want") */
static void hex_refused(const char *name, unsigned line, const char *want)
{
    char err[ERRN], head[300];
    const char *path = put(name, hex, strlen(hex));
    if (line) snprintf(head, sizeof head, "%s:%u: %s", path, line, want);
    else snprintf(head, sizeof head, "%s: %s", path, want);
    int rc = load(path, BOARD_MCU, 0, err, NULL);
    if (rc != -1 || strncmp(err, head, strlen(head)) != 0 || strchr(err, '\n'))
        fail_msg("%s: rc %d, '%s' (want '%s')", name, rc, err, head);
}

/* the start of line n (1-based) of hex */
static char *line_at(unsigned n)
{
    char *p = hex;
    while (--n) p = strchr(p, '\n') + 1;
    return p;
}

static void test_hex_good_loads_same_flash(void **state)
{
    (void)state;
    char err[ERRN];
    static avrhost_t ha, hb;
    hex_of_image(1);
    strcat(hex, "\n\r\n");
    for (char *p = strchr(line_at(2), '\n'); p == strchr(line_at(2), '\n'); p = NULL) memmove(p + 1, p, strlen(p) + 1), *p = '\r';
    const char *path = put("good.hex", hex, strlen(hex));
    assert_int_equal(load(path, BOARD_MCU, 0, err, &ha), 0);
    assert_int_equal(load(BASE_IMAGE, BOARD_MCU, 0, err, &hb), 0);
    assert_memory_equal(ha.avr->flash, hb.avr->flash, ha.avr->flashend + 1u);
    assert_memory_equal(ha.avr->flash, flash, flash_n);
    avrhost_close(&ha), avrhost_close(&hb);
}

static void test_hex_faults(void **state)
{
    (void)state;
    char *p;
    hex_of_image(1), p = strchr(line_at(3), '\n'), p[-1] = p[-1] == '0' ? '1' : '0';
    hex_refused("checksum.hex", 3, "bad checksum");
    hex_of_image(1), p = line_at(2), memmove(p + 6, p, strlen(p) + 1), memcpy(p, "hello\n", 6);
    hex_refused("garbage.hex", 2, "not an Intel HEX record");
    hex_of_image(1), line_at(4)[9] = 'G', hex_refused("digit.hex", 4, "a character that is not a hex digit at column 10");
    hex_of_image(1), p = line_at(2), p[1] = '0', p[2] = 'F', hex_refused("length.hex", 2, "its length byte says 15 data bytes, the record has 16");
    hex_of_image(1), p = line_at(5), memmove(p + 1, p + 2, strlen(p + 1)), hex_refused("odd.hex", 5, "a record of");
    hex_of_image(0), hex_refused("truncated.hex", 0, "no end record");
    hex_of_image(0), *line_at(7) = '\0', hex_refused("cut.hex", 0, "no end record");
    hex_of_image(1), rec(hex, 0, 0, flash, 4), hex_refused("after-end.hex", (unsigned)(flash_n + 15) / 16 + 2, "a line after the end record");
    hex_of_image(1), strcat(hex, "garbage\n"), hex_refused("after-end2.hex", (unsigned)(flash_n + 15) / 16 + 2, "a line after the end record");
    uint8_t x[32] = { 0xFF, 0xFF };
    hex_of_image(0), rec(hex, 6, 0, NULL, 0), hex_refused("type6.hex", (unsigned)(flash_n + 15) / 16 + 1, "record type 06");
    hex_of_image(0), rec(hex, 4, 0, x, 2), rec(hex, 0, 0xFFF0, x, 32), rec(hex, 1, 0, NULL, 0);
    hex_refused("wrap.hex", (unsigned)(flash_n + 15) / 16 + 2, "its bytes wrap past the end of their 64 KiB segment");
    hex_of_image(0), rec(hex, 4, 0, x, 2), rec(hex, 0, 0x10, x, 16), rec(hex, 1, 0, NULL, 0);
    hex_refused("beyond.hex", (unsigned)(flash_n + 15) / 16 + 2, "bytes at 0xFFFF0010 beyond any AVR's flash (262144 bytes)");
    x[0] = 0x10, x[1] = 0x00;
    hex_of_image(0), rec(hex, 2, 0, x, 2), rec(hex, 0, 0x10, x, 16), rec(hex, 1, 0, NULL, 0);
    hex_refused("oversize.hex", 0, "bytes up to 0x1001F: larger than the atmega328p's flash (32768 bytes)");
    hex_of_image(0), rec(hex, 4, 0, x, 3), hex_refused("ext-len.hex", (unsigned)(flash_n + 15) / 16 + 1, "an extended address record with 3 data bytes");
    hex_of_image(0), rec(hex, 1, 0, x, 1), hex_refused("end-data.hex", (unsigned)(flash_n + 15) / 16 + 1, "an end record with data");
    hex[0] = '\0', rec(hex, 1, 0, NULL, 0), hex_refused("empty.hex", 0, "no data records");
}

/* a deterministic pseudo-random number (a 64-bit LCG's high bits) */
static uint32_t rnd(uint64_t *s)
{
    *s = *s * 6364136223846793005u + 1442695040888963407u;
    return (uint32_t)(*s >> 33);
}

/* random bytes in the ELF header, the section header table, the section
 * names and the symbol table, and in a .mmcu's tags: each image loads
 * or is refused with one line, never a signal (its code is not run: a
 * random jump is the run path's concern, not the loader's) */
static void test_elf_random_bytes(void **state)
{
    (void)state;
    char err[ERRN];
    uint64_t seed = 23;
    int refused_n = 0;
    run_cycles = 0;
    for (int k = 0; k < FUZZ_IMAGES; k++) {
        if (k % 2) mmcu_name_clock(BOARD_MCU, F_CPU_HZ);
        else fresh();
        uint32_t shoff = rd32(buf + 32), sym = rd32(shdr(find(".symtab")) + 16), str = rd32(shdr(rd16(buf + 50)) + 16);
        uint32_t mm = k % 2 ? find(".mmcu") : 0;
        uint32_t from[5] = { 0, shoff, str, sym, mm ? rd32(shdr(mm) + 16) : 0 };
        uint32_t span[5] = { 52, nsec() * 40u, 64, 256, mm ? rd32(shdr(mm) + 20) : 0 };
        for (int i = 0; i < FUZZ_BYTES; i++) {
            int r = (int)(rnd(&seed) % (mm ? 5u : 4u));
            buf[from[r] + rnd(&seed) % span[r]] = (uint8_t)rnd(&seed);
        }
        char name[40];
        snprintf(name, sizeof name, "fuzz%03d.elf", k);
        const char *path = put(name, buf, buf_n);
        if (load(path, k % 3 ? BOARD_MCU : NULL, 0, err, NULL) != 0) {
            refused_n++;
            if (strchr(err, '\n') || strncmp(err, path, strlen(path)) != 0) fail_msg("%s: '%s'", name, err);
        }
    }
    run_cycles = RUN_CYCLES;
    assert_true(refused_n > 0 && refused_n < FUZZ_IMAGES); /* both paths taken */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_elf_header),
        cmocka_unit_test(test_elf_sections),
        cmocka_unit_test(test_mmcu),
        cmocka_unit_test(test_mmcu_trace_never_acts),
        cmocka_unit_test(test_sizes),
        cmocka_unit_test(test_elf_random_bytes),
        cmocka_unit_test(test_hex_good_loads_same_flash),
        cmocka_unit_test(test_hex_faults),
    };
    int rc = cmocka_run_group_tests(tests, setup, teardown);
    free(hex);
    free(flash);
    return rc;
}
