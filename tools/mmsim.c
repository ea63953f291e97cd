/* mmsim - the headless simulator: one contest on one maze, or a batch.
 * A thin main: the flags (a table, tools/cli.h) into run_opts_t, checked
 * together, then sim/contest runs the contest (run.h) or the batch (batch.h).
 *
 * The robot is driven by the mouse's own firmware in-process (hal/sim) by
 * default; `--driver scripted` drives it with a stand-in on the true pose
 * and maze (sim/contest/driver.h), and --serial/--pty/--avr and --mms hand
 * the driving to an MCU or an mms algorithm.
 * Exit codes: 0 ok, 1 goal not reached, 2 bad input, 3 external failure;
 * a batch returns the worst. */
#include <errno.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "cli.h"
#include "arm/stm32board.h"
#include "board/board.h"
#include "contest/batch.h"
#include "contest/contest.h"
#include "contest/run.h"
#include "io/datadir.h"
#include "io/outfile.h"
#include "io/stdstream.h"
#include "link/serial.h"
#include "validate/steplog.h"
#include "validate/validate.h"
#include "view/report.h"

typedef struct {
    run_opts_t run;
    const char *maze, *batch, *bench_log, *contest;
    int help, validate, print_contest;
} mmsim_opts_t;

#define RUN(field) offsetof(mmsim_opts_t, run.field)

static void usage(FILE *out)
{
    fputs("usage: mmsim --maze FILE [--config FILE|-] [--robot FILE] [--seed N] [--time-limit S] [--runs N]\n"
          "             [--centre-post on|off] [--profile default|paper] [--driver firmware|scripted]\n"
          "             [--json] [--realtime] [--verbose] [--report FILE.png]\n"
          "             (--runs: speed runs after the search, default 3; scripted: runs to the goal)\n"
          "             (--time-limit: the contest clock, from the mouse first leaving the start cell, as laps;\n"
          "             a run under way at the limit may end up to 60 s later, flagged over time)\n"
          "             [--lcm[=URL]] [--lcm-log FILE] [--lcm-rate HZ]   (LCM telemetry, sim/telemetry/telem.h)\n"
          "             [--gui [--speed 1..64]] [--screenshot FILE.png [--at SECONDS]]\n"
          "             [--camera 1|2|3] [--size WxH]   (viewer)\n"
          "       mmsim --maze FILE --serial DEV|--port DEV|--pty [--baud N] [--protocol framed|compat]\n"
          "             [--silence-ms 0..60000]   (hardware in the loop: an MCU drives over a serial link,\n"
          "             in real time; --pty creates a pseudo-terminal and prints its path; docs/PROTOCOL.md;\n"
          "             motors off after N ms without a message: framed 100 by default, compat never; 0 never)\n"
          "       mmsim --maze FILE --avr ELF [--mcu NAME] [--f-cpu HZ] [--baud N] [--protocol P] [--silence-ms N]\n"
          "             [--watch NAME[,NAME...]]   (processor in the loop: the AVR image runs in simavr, in lockstep;\n"
          "             --watch as for --board)\n"
          "       --gdb PORT with --avr (and --board): simavr's gdb stub on 127.0.0.1:PORT; the firmware and the\n"
          "             whole simulation halt until avr-gdb attaches (target remote :PORT) and continues, and at each\n"
          "             breakpoint or step; the JSON is the run's without --gdb (sim/board/README.md)\n"
          "       mmsim --maze FILE --board NAME|FILE --avr FIRMWARE.elf|.hex [--robot FILE] [--input \"T ACTION; ...\"]\n"
          "             [--goal X,Y] [--eeprom FILE] [--console pty]   (the image on an emulated board, boards/NAME-*.ini:\n"
          "             pins, PWM, encoders, ADC,\n"
          "             UART; --verbose echoes its console; --input: a person's hands, T in sim seconds: switches=N,\n"
          "             button, button=SECONDS|down|up, reset, occlude=SENSOR (a robot-file [ir.*]/[tof.*] name, or left|right),\n"
          "             push=DX_MM[,DYAW_DEG[,SECONDS]], lift, place, send=TEXT, end; several --input add up;\n"
          "             --eeprom FILE: the MCU's EEPROM, a raw image, loaded at power-on and saved at the end;\n"
          "             --end-on TEXT: the run ends when the console prints TEXT (exit_reason console_end);\n"
          "             --console pty: the board's UART on a pseudo-terminal (its path printed), in real time;\n"
          "             --watch NAME[,NAME...]: the firmware's global variables, by the ELF's symbols and DWARF,\n"
          "             each step on LCM channel MM_WATCH and in --report beside the true pose)\n"
          "       mmsim --maze FILE --board NAME|FILE --firmware IMAGE.elf [--flash FILE] [--input \"T ACTION; ...\"]\n"
          "             [--watch NAME[,NAME...]] [--gdb PORT] [--no-skip]\n"
          "             (an ARM image on an emulated STM32 board, its board file's [board] mcu stm32...: the STM32F103\n"
          "             register by register on libunicorn, sim/arm/README.md; --input: button, button=SECONDS|down|up,\n"
          "             occlude, push, lift, place, end; --flash FILE: the whole flash, loaded under the image at\n"
          "             power-on and saved at the end; --end-on, --verbose, --watch as for --avr; --gdb PORT: the stub for\n"
          "             gdb-multiarch (set osabi none; target remote :PORT), the same JSON; --no-skip: WFI and wait loops\n"
          "             run cycle by cycle, not jumped over: the same JSON but board.skipped)\n"
          "       mmsim --maze FILE --mms COMMAND [--mms-ideal-walls] [--mms-timeout-ms N] [--mms-reset-at S|idle]\n"
          "             (an mms algorithm drives the robot through the mms text API, docs/MMS.md)\n"
          "       mmsim --batch DIR [--jobs N] [options as above]   (one JSON line per maze)\n"
          "       mmsim --print-config [--config FILE]   mmsim --print-robot [--robot FILE]   (robot files: docs/ROBOTS.md)\n"
          "       --contest NAME|FILE: a contest's rules, contests/NAME.ini (classic-japan, classic-uk, halfsize-japan, apec):\n"
          "             maze geometry, start, goal, time limit, runs, scoring; the score in the JSON's \"contest\";\n"
          "             mmsim --print-contest --contest NAME|FILE prints the profile (contests/README.md)\n"
          "       mmsim --validate [--config FILE] [--robot FILE] [--json]   (fitted figures and graded predictions, each with its source; 0 iff every prediction passes)\n"
          "       mmsim --bench-log fwd:V|rot:V|ir:NAME:D_MM:DEG [--robot FILE]   (a step or IR log as CSV, for tools/mmfit)\n"
          "Exit codes: 0 ok, 1 goal not reached, 2 bad input, 3 external failure.\n",
          out);
}

static int bad(const char *fmt, const char *arg) { return cli_bad("mmsim", fmt, arg); }
static run_opts_t *run_of(void *o) { return &((mmsim_opts_t *)o)->run; }

static int f_seed(const char *prog, void *o, const char *arg)
{
    double v;
    if (cli_number(prog, "--seed", arg, 0, 9007199254740992.0, &v)) return CLI_BAD_INPUT;
    if (v != floor(v)) return bad("--seed: expected a whole number, got '%s'", arg);
    run_of(o)->seed = (uint64_t)v;
    return 0;
}

static int f_input(const char *prog, void *o, const char *arg)
{
    char err[300];
    if (input_add(&run_of(o)->input, arg, err, sizeof err) != 0) return bad("%s", err);
    return 0;
}

static int f_console(const char *prog, void *o, const char *arg)
{
    if (strcmp(arg, "pty") != 0) return bad("--console: expected pty, got '%s'", arg);
    run_of(o)->console_pty = 1;
    return 0;
}

static int f_goal(const char *prog, void *o, const char *arg)
{
    int x, y, n = 0;
    if (sscanf(arg, "%d,%d%n", &x, &y, &n) != 2 || arg[n] || x < 0 || y < 0 || x > 255 || y > 255)
        return bad("--goal: expected X,Y (a cell, e.g. 7,7), got '%s'", arg);
    run_of(o)->goal_x = x;
    run_of(o)->goal_y = y;
    return 0;
}

static int f_centre_post(const char *prog, void *o, const char *arg)
{
    if (!strcmp(arg, "on")) run_of(o)->centre_post = 1;
    else if (!strcmp(arg, "off")) run_of(o)->centre_post = 0;
    else return bad("--centre-post: expected on or off, got '%s'", arg);
    return 0;
}

static int f_profile(const char *prog, void *o, const char *arg)
{
    if (!strcmp(arg, "paper")) run_of(o)->paper_friction = 1;
    else if (strcmp(arg, "default")) return bad("--profile: expected default or paper, got '%s'", arg);
    return 0;
}

static int f_driver(const char *prog, void *o, const char *arg)
{
    if (strcmp(arg, "scripted") && strcmp(arg, "firmware")) return bad("--driver: expected firmware or scripted, got '%s'", arg);
    run_of(o)->scripted = !strcmp(arg, "scripted");
    return 0;
}

static int f_lcm(const char *prog, void *o, const char *arg)
{
    /* the providers liblcm has (lcm/lcm.c: udpm, file, memq, tcpq, mpudpm): a
     * name it cannot have is bad input now, not a failure to open later */
    static const char *const providers[] = { "udpm", "file", "memq", "tcpq", "mpudpm" };
    run_of(o)->telem.url = arg ? arg : "";
    if (!arg) return 0;
    const char *sep = strstr(arg, "://");
    if (!sep) return bad("--lcm: expected an LCM URL like udpm://239.255.76.67:7667?ttl=0, got '%s'", arg);
    for (size_t i = 0; i < sizeof providers / sizeof providers[0]; i++)
        if ((size_t)(sep - arg) == strlen(providers[i]) && !strncmp(arg, providers[i], (size_t)(sep - arg))) return 0;
    return bad("--lcm: '%s': the provider is udpm, file, memq, tcpq or mpudpm (e.g. udpm://239.255.76.67:7667?ttl=0)", arg);
}

static int f_lcm_log(const char *prog, void *o, const char *arg)
{
    if (!*arg) return bad("%s", "--lcm-log: expected a file name");
    run_of(o)->telem.log_path = arg;
    return 0;
}

static int f_camera(const char *prog, void *o, const char *arg) { return cli_view_option(prog, "camera", arg, &run_of(o)->view); }
static int f_speed(const char *prog, void *o, const char *arg) { return cli_view_option(prog, "speed", arg, &run_of(o)->view); }
static int f_size(const char *prog, void *o, const char *arg) { return cli_view_option(prog, "size", arg, &run_of(o)->view); }

/* --serial DEV or --port DEV (the viewer shows it) */
static int f_serial(const char *prog, void *o, const char *arg)
{
    run_of(o)->link.device = arg;
    run_of(o)->view.port = arg;
    return 0;
}

/* the link's rate, shown by the viewer */
static int f_baud(const char *prog, void *o, const char *arg)
{
    double v;
    if (cli_number(prog, "--baud", arg, 50, SERIAL_BAUD_MAX, &v)) return CLI_BAD_INPUT;
    if (v != floor(v)) return bad("--baud: expected a whole number of bits/s, got '%s'", arg);
    run_of(o)->link.baud = (uint32_t)v;
    run_of(o)->view.baud = (long)v;
    return 0;
}

static int f_pty(const char *prog, void *o, const char *arg)
{
    run_of(o)->link.pty = 1;
    return 0;
}

static int f_protocol(const char *prog, void *o, const char *arg)
{
    if ((run_of(o)->link.protocol = link_parse_protocol(arg)) < 0) return bad("--protocol: expected framed or compat, got '%s'", arg);
    return 0;
}

static int f_silence(const char *prog, void *o, const char *arg)
{
    double v;
    if (cli_number(prog, "--silence-ms", arg, 0, 60000, &v)) return CLI_BAD_INPUT; /* 0 = no watchdog */
    run_of(o)->link.silence_s = v / 1000.0;
    return 0;
}

static int f_f_cpu(const char *prog, void *o, const char *arg)
{
    double v;
    if (cli_number(prog, "--f-cpu", arg, 1e6, 32e6, &v)) return CLI_BAD_INPUT; /* Hz: the clocks AVRs run at */
    run_of(o)->avr_f_cpu = (uint32_t)v;
    return 0;
}

/* --gdb PORT: a TCP port on 127.0.0.1 for avr-gdb */
static int f_gdb(const char *prog, void *o, const char *arg)
{
    double v;
    if (cli_number(prog, "--gdb", arg, 1, 65535, &v)) return CLI_BAD_INPUT;
    if (v != floor(v)) return bad("--gdb: expected a TCP port, a whole number from 1 to 65535, got '%s'", arg);
    run_of(o)->gdb_port = (unsigned)v;
    return 0;
}

static int f_mms(const char *prog, void *o, const char *arg)
{
    if (!*arg) return bad("%s", "--mms: expected a command, e.g. --mms 'python3 main.py'");
    run_of(o)->mms.command = arg;
    return 0;
}

/* --mms-reset-at S (sim time, s) or idle (each time the algorithm waits for Reset) */
static int f_mms_reset_at(const char *prog, void *o, const char *arg)
{
    if (!strcmp(arg, "idle")) {
        run_of(o)->mms.reset_on_idle = 1;
        return 0;
    }
    char *end;
    double v = strtod(arg, &end);
    if (!*arg || *end || !(v >= 0 && v <= 86400))
        return bad("--mms-reset-at: expected seconds of simulation time from 0 to 86400, or idle, got '%s'", arg);
    run_of(o)->mms.reset_at_s = v;
    return 0;
}


/* --watch NAME[,NAME...]: several --watch add up */
static int f_watch(const char *prog, void *o, const char *arg)
{
    static char names[1024];
    size_t at = strlen(names);
    if (at + 1 + strlen(arg) >= sizeof names) return bad("--watch: the names are longer than %s", "1023 characters");
    snprintf(names + at, sizeof names - at, "%s%s", at ? "," : "", arg);
    run_of(o)->watch = names;
    return 0;
}

static const cli_opt_t flags[] = {
    { .name = "maze", .kind = CLI_STR, .off = offsetof(mmsim_opts_t, maze) },
    { .name = "batch", .kind = CLI_STR, .off = offsetof(mmsim_opts_t, batch) },
    { .name = "help", .kind = CLI_SET, .off = offsetof(mmsim_opts_t, help) },
    { .name = "validate", .kind = CLI_SET, .off = offsetof(mmsim_opts_t, validate) },
    { .name = "bench-log", .kind = CLI_STR, .off = offsetof(mmsim_opts_t, bench_log) },
    { .name = "config", .kind = CLI_STR, .off = RUN(config_path) },
    { .name = "robot", .kind = CLI_STR, .off = RUN(robot_path) },
    { .name = "input", .kind = CLI_FN, .fn = f_input, .has_arg = 1 },
    { .name = "goal", .kind = CLI_FN, .fn = f_goal, .has_arg = 1 },
    { .name = "console", .kind = CLI_FN, .fn = f_console, .has_arg = 1 },
    { .name = "print-robot", .kind = CLI_SET, .off = RUN(print_robot) },
    { .name = "contest", .kind = CLI_STR, .off = offsetof(mmsim_opts_t, contest) },
    { .name = "print-contest", .kind = CLI_SET, .off = offsetof(mmsim_opts_t, print_contest) },
    { .name = "seed", .kind = CLI_FN, .fn = f_seed, .has_arg = 1 },
    { .name = "time-limit", .kind = CLI_NUM, .off = RUN(time_limit_s), .lo = 1, .hi = 86400 },
    { .name = "json", .kind = CLI_SET, .off = RUN(json) },
    { .name = "realtime", .kind = CLI_SET, .off = RUN(realtime) },
    { .name = "runs", .kind = CLI_INT, .off = RUN(runs), .lo = 1, .hi = 64 },
    { .name = "centre-post", .kind = CLI_FN, .fn = f_centre_post, .has_arg = 1 },
    { .name = "print-config", .kind = CLI_SET, .off = RUN(print_config) },
    { .name = "jobs", .kind = CLI_INT, .off = RUN(jobs), .lo = 1, .hi = 256 },
    { .name = "profile", .kind = CLI_FN, .fn = f_profile, .has_arg = 1 },
    { .name = "driver", .kind = CLI_FN, .fn = f_driver, .has_arg = 1 },
    { .name = "verbose", .kind = CLI_SET, .off = RUN(verbose) },
    { .name = "lcm", .kind = CLI_FN, .fn = f_lcm, .has_arg = 2 },
    { .name = "lcm-log", .kind = CLI_FN, .fn = f_lcm_log, .has_arg = 1 },
    { .name = "lcm-rate", .kind = CLI_NUM, .off = RUN(telem.rate_hz), .lo = 1, .hi = 1000 },
    { .name = "report", .kind = CLI_STR, .off = RUN(report) },
    { .name = "gui", .kind = CLI_SET, .off = RUN(gui) },
    { .name = "screenshot", .kind = CLI_STR, .off = RUN(shot) },
    { .name = "at", .kind = CLI_NUM, .off = RUN(shot_at_s), .lo = 0, .hi = 86400 },
    { .name = "camera", .kind = CLI_FN, .fn = f_camera, .has_arg = 1 },
    { .name = "size", .kind = CLI_FN, .fn = f_size, .has_arg = 1 },
    { .name = "speed", .kind = CLI_FN, .fn = f_speed, .has_arg = 1 },
    { .name = "port", .kind = CLI_FN, .fn = f_serial, .has_arg = 1 },
    { .name = "serial", .kind = CLI_FN, .fn = f_serial, .has_arg = 1 },
    { .name = "baud", .kind = CLI_FN, .fn = f_baud, .has_arg = 1 },
    { .name = "pty", .kind = CLI_FN, .fn = f_pty, .has_arg = 0 },
    { .name = "protocol", .kind = CLI_FN, .fn = f_protocol, .has_arg = 1 },
    { .name = "silence-ms", .kind = CLI_FN, .fn = f_silence, .has_arg = 1 },
    { .name = "avr", .kind = CLI_STR, .off = RUN(avr_elf) },
    { .name = "mcu", .kind = CLI_STR, .off = RUN(avr_mcu) },
    { .name = "board", .kind = CLI_STR, .off = RUN(board) },
    { .name = "eeprom", .kind = CLI_STR, .off = RUN(eeprom_path) },
    { .name = "firmware", .kind = CLI_STR, .off = RUN(arm_elf) },
    { .name = "flash", .kind = CLI_STR, .off = RUN(flash_path) },
    { .name = "end-on", .kind = CLI_STR, .off = RUN(end_on) },
    { .name = "no-skip", .kind = CLI_SET, .off = RUN(no_skip) },
    { .name = "watch", .kind = CLI_FN, .fn = f_watch, .has_arg = 1 },
    { .name = "f-cpu", .kind = CLI_FN, .fn = f_f_cpu, .has_arg = 1 },
    { .name = "gdb", .kind = CLI_FN, .fn = f_gdb, .has_arg = 1 },
    { .name = "mms", .kind = CLI_FN, .fn = f_mms, .has_arg = 1 },
    { .name = "mms-ideal-walls", .kind = CLI_SET, .off = RUN(mms.ideal_walls) },
    { .name = "mms-timeout-ms", .kind = CLI_INT, .off = RUN(mms.timeout_ms), .lo = 1, .hi = 3600000 },
    { .name = "mms-reset-at", .kind = CLI_FN, .fn = f_mms_reset_at, .has_arg = 1 },
    { NULL },
};

/* The flags that only make sense together: 0, or CLI_BAD_INPUT after one line. */
static int check_combinations(mmsim_opts_t *m, const int *seen)
{
    run_opts_t *o = &m->run;
    int link_flags = cli_seen(flags, seen, "protocol") + cli_seen(flags, seen, "silence-ms");
    int mms_flags = cli_seen(flags, seen, "mms-ideal-walls") + cli_seen(flags, seen, "mms-timeout-ms") +
                    cli_seen(flags, seen, "mms-reset-at");
    if (o->arm_elf && (!o->board || o->avr_elf))
        return bad("%s", "--firmware IMAGE.elf runs on an STM32 board: with --board NAME, not with --avr");
    if (o->flash_path && !o->arm_elf) return bad("%s", "--flash FILE needs --board NAME --firmware IMAGE.elf (an STM32 board)");
    if (o->arm_elf && (o->eeprom_path || o->console_pty))
        return bad("%s", "--firmware (an STM32 board): not with --eeprom (its flash: --flash FILE) or --console pty");
    if (o->no_skip && !o->arm_elf) return bad("%s", "--no-skip needs --board NAME --firmware IMAGE.elf (an ARM core's idle skipping)");
    if (o->board && !o->avr_elf && !o->arm_elf)
        return bad("%s", "--board NAME needs --avr FIRMWARE.elf|.hex (an AVR board) or --firmware IMAGE.elf (an STM32 board)");
    if (o->board && (o->link.device || o->link.pty || link_flags || o->avr_mcu || o->avr_f_cpu || o->mms.command))
        return bad("%s", "--board: the image runs on the board file's MCU: not with --serial/--pty, --protocol, --silence-ms, --mcu, --f-cpu or --mms");
    if (o->board && m->batch && (o->eeprom_path || o->flash_path || o->console_pty || o->gdb_port))
        return bad("%s", "--board with --batch: each maze's board on its own; not with --eeprom, --flash, --console pty or --gdb");
    o->serial = o->link.device || o->link.pty || (o->avr_elf && !o->board);
    if (!!o->link.device + o->link.pty + !!o->avr_elf > 1) return bad("%s", "--serial/--port, --pty and --avr exclude each other");
    if (!o->serial && link_flags) return bad("%s", "--protocol and --silence-ms need --serial DEV, --pty or --avr ELF");
    if (!o->avr_elf && (o->avr_mcu || o->avr_f_cpu)) return bad("%s", "--mcu and --f-cpu need --avr ELF");
    if (o->gdb_port && !o->avr_elf && !o->arm_elf)
        return bad("%s", "--gdb PORT needs --avr FIRMWARE (with or without --board) or --board NAME --firmware IMAGE.elf");
    if (!o->mms.command && mms_flags) return bad("%s", "--mms-ideal-walls, --mms-timeout-ms and --mms-reset-at need --mms COMMAND");
    if (o->mms.command && o->verbose) o->mms.trace = stderr; /* --verbose: the mms dialogue too */
    if (o->mms.command && o->gui) o->mms.idle_wait = 1; /* an idle algorithm waits for the viewer's Reset button */
    if (o->mms.command && !cli_seen(flags, seen, "driver")) o->scripted = 0; /* the firmware's motion layer runs the moves */
    if (o->mms.command && (o->serial || o->scripted || m->batch))
        return bad("%s", "--mms drives the firmware of one run: not with --serial/--pty/--avr, --driver scripted or --batch");
    if (o->serial && m->batch) return bad("%s", "--serial/--pty/--avr run one maze, not --batch");
    if (o->serial && !o->avr_elf) o->realtime = 1; /* a real MCU runs in real time; simavr in lockstep */
    if (m->batch && m->maze) return bad("%s", "--maze and --batch: one at a time (a batch runs every maze in DIR)");
    if (o->console_pty && !o->board) return bad("%s", "--console pty needs --board NAME");
    if (o->eeprom_path && !o->board) return bad("%s", "--eeprom FILE needs --board NAME");
    if (o->end_on && !o->board) return bad("%s", "--end-on TEXT needs --board NAME");
    if (o->end_on && (!*o->end_on || strlen(o->end_on) > RUN_END_ON_MAX))
        return bad("%s", "--end-on TEXT: 1 to 64 characters (RUN_END_ON_MAX)");
    if (o->watch && !o->avr_elf && !o->arm_elf)
        return bad("%s", "--watch NAME needs --avr IMAGE.elf (with or without --board NAME) or --firmware IMAGE.elf: the image's variables");
    if (o->console_pty) o->realtime = 1; /* a person at a serial monitor: in real time */
    if (o->view.baud <= 0) o->view.baud = (long)link_default_baud(o->link.protocol); /* the viewer's Connect */
    if (cli_seen(flags, seen, "at") && !o->shot) return bad("%s", "--at SECONDS needs --screenshot FILE.png (the moment it is taken)");
    if (cli_seen(flags, seen, "speed") && !o->gui) return bad("%s", "--speed needs --gui (the viewer's playback speed)");
    if (cli_seen(flags, seen, "jobs") && !m->batch) return bad("%s", "--jobs N needs --batch DIR (the mazes run at once)");
    if ((m->validate || m->bench_log) && (m->maze || m->batch))
        return bad("%s", "--validate and --bench-log run their own benches: not with --maze or --batch");
    if (o->print_config || o->print_robot || m->print_contest || m->validate || m->bench_log) return 0;
    if (m->batch && (o->telem.url || o->telem.log_path)) return bad("%s", "--lcm and --lcm-log work on one maze, not with --batch");
    if (m->batch && (o->report || o->gui || o->shot)) return bad("%s", "--report, --gui and --screenshot need --maze (one run), not --batch");
    if (o->gui && o->shot) return bad("%s", "--gui and --screenshot: one at a time");
    if (!m->batch && !m->maze) return bad("%s", "--maze FILE is required");
    return 0;
}

/* A name whose extension, if it has one, is .png (any case): the picture is
 * a PNG whatever its name, so another extension is a mistake. */
static int png_or_no_ext(const char *path)
{
    const char *base = strrchr(path, '/'), *dot = strrchr(base ? base + 1 : path, '.');
    return !dot || dot == (base ? base + 1 : path) || strcasecmp(dot, ".png") == 0;
}

/* --report (its PNG, SVG, JSON and plots PNG) and --screenshot fail now, not after a
 * ten-minute contest: an empty name, a folder, a path that cannot be written. */
static int probe_outputs(const run_opts_t *o)
{
    char paths[REPORT_FILES + 1][4096], perr[600];
    const char *flag[REPORT_FILES + 1] = { "--report", "--report", "--report", "--report", "--screenshot" };
    int n = 0;
    for (int k = 0; k < 2; k++) { /* each writes a PNG: a name that says otherwise is a mistake */
        const char *name = k ? o->shot : o->report;
        if (name && !png_or_no_ext(name)) {
            fprintf(stderr, "mmsim: %s %s: it writes a PNG: give a name ending in .png\n", k ? "--screenshot" : "--report", name);
            return RUN_BAD_INPUT;
        }
    }
    if (o->report) {
        snprintf(paths[n++], sizeof paths[0], "%s", o->report);
        report_sibling(o->report, ".svg", paths[n++], sizeof paths[0]);
        report_sibling(o->report, ".json", paths[n++], sizeof paths[0]);
        report_sibling(o->report, "-plots.png", paths[n++], sizeof paths[0]);
    }
    if (o->shot) {
        flag[n] = "--screenshot";
        snprintf(paths[n++], sizeof paths[0], "%s", o->shot);
    }
    for (int i = 0; i < n; i++)
        if (outfile_probe(paths[i], perr, sizeof perr) != 0) {
            fprintf(stderr, "mmsim: %s: %s\n", flag[i], perr);
            return RUN_BAD_INPUT;
        }
    return 0;
}

/* --validate: every model check (sim/validate) with this config; 0 iff every
 * graded prediction passes (fitted figures are reported, never graded). */
static int validate(const run_opts_t *o)
{
    simcfg_t cfg;
    validate_check_t checks[VALIDATE_MAX_CHECKS];
    if (run_load_config(o, &cfg) != 0) return RUN_BAD_INPUT;
    int n = validate_run(&cfg, checks);
    validate_summary_t sum = validate_summary(checks, n);
    if (o->json) {
        json_t *j = validate_json(checks, n);
        int rc = run_json_line(j);
        json_decref(j);
        if (rc) return RUN_EXTERNAL;
    } else {
        validate_print(checks, n, stdout);
    }
    return sum.passed < sum.graded ? RUN_NOT_REACHED : RUN_OK;
}

/* --board with an STM32 board file at path: read once (o->arm_board_spec);
 * without --robot, its default_robot. 0, or CLI_BAD_INPUT after one line. */
static int arm_board(run_opts_t *o, const char *path)
{
    static stm32board_spec_t spec; /* large */
    char err[1200];
    if (!o->arm_elf) {
        fprintf(stderr, "mmsim: --board %s: %s is an STM32 board: give its image with --firmware IMAGE.elf\n", o->board, path);
        return CLI_BAD_INPUT;
    }
    if (stm32board_load(&spec, path, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return CLI_BAD_INPUT;
    }
    o->arm_board_spec = &spec;
    if (!o->robot_path && spec.default_robot[0]) o->robot_path = spec.default_robot;
    return 0;
}

/* --board: the board file read once (o->board_spec); without --robot, the
 * board's default_robot. 0, or CLI_BAD_INPUT after one line. */
static int board_default_robot(run_opts_t *o)
{
    static board_spec_t spec; /* large */
    char path[512], err[1200];
    if (board_find(o->board, path, sizeof path, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return CLI_BAD_INPUT;
    }
    /* the board file's MCU picks the core: sim/arm's reader for an STM32, sim/board's for an AVR */
    if (boardfile_family(path, err, sizeof err) == BOARDFILE_STM32) return arm_board(o, path);
    if (o->arm_elf) {
        fprintf(stderr, "mmsim: --board %s: %s is an AVR board: give its image with --avr FIRMWARE.elf|.hex\n", o->board, path);
        return CLI_BAD_INPUT;
    }
    if (board_load(&spec, path, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return CLI_BAD_INPUT;
    }
    o->board_spec = &spec;
    if (!o->robot_path && spec.default_robot[0]) o->robot_path = spec.default_robot;
    return 0;
}

/* --robot NAME (no '/', no .ini): robots/NAME.ini in the working directory,
 * an installed tree or the source tree (io/datadir.h). 0, or CLI_BAD_INPUT
 * after one line. */
static int find_robot(run_opts_t *o)
{
    static char path[DATADIR_PATH_MAX + 64];
    char rel[300];
    if (o->board && board_default_robot(o) != 0) return CLI_BAD_INPUT;
    if (!o->robot_path || strchr(o->robot_path, '/') || strstr(o->robot_path, ".ini")) return 0;
    if (snprintf(rel, sizeof rel, "robots/%s.ini", o->robot_path) >= (int)sizeof rel || datadir_find(rel, path, sizeof path) != 0)
        return bad("--robot %s: no robots/NAME.ini of that name here, installed or in the source tree (give the robot file's path)",
                   o->robot_path);
    o->robot_path = path;
    return 0;
}

/* --contest NAME|FILE: the contest file found and read once; without
 * --runs, its number of runs (the firmware's search is the first of them).
 * 0, or CLI_BAD_INPUT after one line. */
static int load_contest(mmsim_opts_t *m, const int *seen)
{
    static contest_t contest;
    char path[DATADIR_PATH_MAX + 64], err[600];
    if (!m->contest) return m->print_contest ? bad("%s", "--print-contest needs --contest NAME|FILE") : 0;
    if (contest_find(m->contest, path, sizeof path, err, sizeof err) != 0) return bad("%s", err);
    if (contest_load(&contest, path, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err); /* FILE:LINE:COL: as the file's other errors */
        return CLI_BAD_INPUT;
    }
    m->run.contest = &contest;
    if (!cli_seen(flags, seen, "runs") && contest.rules.runs > 0)
        m->run.runs = m->run.scripted || contest.rules.runs == 1 ? contest.rules.runs : contest.rules.runs - 1;
    return 0;
}

/* --config -: standard input read once, at most CONFIG_MAX_BYTES, into
 * o->config_text (kept to the end). 0, or RUN_BAD_INPUT after one line. */
static int read_config_stdin(run_opts_t *o, const char *maze)
{
    if (!o->config_path || strcmp(o->config_path, "-") != 0) return 0;
    if (maze && strcmp(maze, "-") == 0) return bad("%s", "--config - and --maze -: only one of them can read standard input");
    static char text[CONFIG_MAX_BYTES + 2];
    size_t n = fread(text, 1, CONFIG_MAX_BYTES + 1, stdin);
    if (ferror(stdin)) return bad("--config -: <stdin>: cannot read: %s", strerror(errno));
    if (n > CONFIG_MAX_BYTES) return bad("%s", "--config -: <stdin>: too large (more than 1 MiB: CONFIG_MAX_BYTES)");
    text[n] = '\0';
    if (memchr(text, '\0', n)) return bad("%s", "--config -: <stdin>: a NUL byte: not a text file");
    o->config_text = text;
    return 0;
}

static int run(int argc, char **argv)
{
    mmsim_opts_t m = { .run = { /* the mouse's own firmware by default, 3 speed runs after the search */
        .seed = 1, .runs = 3, .centre_post = -1, .scripted = 0, .jobs = 1, .goal_x = -1, .goal_y = -1,
        .view = { .width = 1024, .height = 720, .speed = 1, .camera = 1, .port = "", .baud = 0 }, /* baud 0: the protocol's */
        .link = { .protocol = LINK_FRAMED, .silence_s = -1 }, /* silence: the protocol's default */
        .mms = { .timeout_ms = 5000, .reset_at_s = -1 },
    } };
    int seen[sizeof flags / sizeof flags[0]] = { 0 }, first;
    if (cli_parse("mmsim", flags, argc, argv, &m, seen, &first)) return RUN_BAD_INPUT;
    if (m.help) {
        usage(stdout);
        return RUN_OK;
    }
    if (first != argc) return bad("unexpected argument '%s'", argv[first]);
    if (check_combinations(&m, seen) || load_contest(&m, seen) || find_robot(&m.run) || read_config_stdin(&m.run, m.maze))
        return RUN_BAD_INPUT;
    if (m.print_contest) {
        contest_print(m.run.contest, stdout);
        return RUN_OK;
    }
    if (m.validate) return validate(&m.run);
    if (m.bench_log) {
        simcfg_t cfg;
        if (run_load_config(&m.run, &cfg) != 0) return RUN_BAD_INPUT;
        return steplog_run(&cfg, m.bench_log, stdout) ? RUN_BAD_INPUT : RUN_OK;
    }
    if (m.run.print_config || m.run.print_robot) {
        simcfg_t cfg;
        if (run_load_config(&m.run, &cfg) != 0) return RUN_BAD_INPUT;
        if (m.run.print_config) config_print(&cfg, stdout);
        if (m.run.print_robot) robot_print(&cfg, stdout);
        return RUN_OK;
    }
    if (m.batch) return batch_run(&m.run, m.batch);
    if (probe_outputs(&m.run)) return RUN_BAD_INPUT;
    json_t *j;
    int rc = run_one(&m.run, m.maze, &j, !m.run.json);
    if (j && m.run.json && run_json_line(j) != 0) rc = RUN_EXTERNAL;
    json_decref(j);
    return rc;
}

int main(int argc, char **argv)
{
    io_stdout_open("mmsim");
    int rc = run(argc, argv);
    return io_stdout_close("mmsim") != 0 ? RUN_EXTERNAL : rc;
}
