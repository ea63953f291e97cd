/* run.h - one contest on one maze, set up for its driver and run to its end:
 * what `mmsim --maze` does (tools/mmsim.c parses the flags into run_opts_t
 * and calls run_one; batch.h runs many).
 *
 * Drivers (run_driver.h): the mouse's firmware in-process (hal/sim, the
 * default), the scripted stand-in (driver.h), an MCU over a serial link
 * (--serial/--pty) or an AVR image in simavr (--avr; on an emulated board
 * with --board: run_board.c), an mms algorithm
 * driving the firmware's motion layer (--mms).
 * Exit codes: RUN_OK, RUN_NOT_REACHED, RUN_BAD_INPUT, RUN_EXTERNAL. */
#ifndef RUN_H
#define RUN_H

#include <jansson.h>
#include <stdint.h>

#include "link/link.h"
#include "mms/mms.h"
#include "telemetry/telem.h"
#include "view/view.h"
#include "contest/input.h"
#include "world/config.h"

enum { RUN_OK = 0, RUN_NOT_REACHED = 1, RUN_BAD_INPUT = 2, RUN_EXTERNAL = 3 };

#define RUN_STALL_S 5.0 /* no progress for this long while driving = crash stop, s */
#define RUN_END_ON_MAX 64 /* characters of --end-on's text */
#define RUN_OVERTIME_S 60.0 /* a run under way at the time limit may finish this much later (flagged over time), s */

typedef struct {
    const char *config_path;
    const char *config_text; /* --config -: standard input's text, read once (batch jobs share it) */
    const char *robot_path; /* --robot FILE (NULL: the paper's robot, built in) */
    uint64_t seed;
    double time_limit_s; /* <= 0: from the config */
    int json, realtime, runs, centre_post, print_config, print_robot;
    int paper_friction; /* --profile paper */
    int scripted;       /* --driver scripted */
    int verbose;        /* --verbose: firmware log lines on stderr */
    int jobs;           /* --batch: runs at a time */
    telem_opts_t telem; /* --lcm[=URL], --lcm-log FILE, --lcm-rate HZ */
    const char *report; /* --report FILE.png, or NULL */
    int gui;            /* --gui: live viewer */
    const char *shot;   /* --screenshot FILE.png, or NULL */
    double shot_at_s;   /* --at: sim time of the screenshot */
    view_opts_t view;   /* --size, --speed, --camera, --port, --baud */
    int serial;         /* --serial/--port, --pty or --avr: an MCU drives over a serial link */
    link_opts_t link;
    const char *avr_elf, *avr_mcu; /* --avr ELF: processor in the loop (simavr), --mcu */
    uint32_t avr_f_cpu;            /* --f-cpu, Hz (0 = from the ELF or 16 MHz) */
    mms_opts_t mms;                /* --mms COMMAND (NULL: none), --mms-ideal-walls, --mms-timeout-ms, --mms-reset-at */
    input_t input;                 /* --input "T ACTION; ...": a person's hands (input.h); input.n 0 = none */
    int goal_x, goal_y;            /* --goal X,Y: laps scored to this cell, not the maze's goal (-1: the maze's) */
    const char *board;             /* --board NAME|FILE: the image (--avr) on an emulated board (sim/board) */
    const struct board_spec_s *board_spec; /* the board file, read once by the caller (NULL: run_board reads it) */
    int console_pty;               /* --console pty: the board's UART0 on a pseudo-terminal (a person's serial monitor) */
    const char *end_on;            /* --end-on TEXT: a board run ends once its console prints TEXT (NULL: never) */
    const char *eeprom_path;       /* --eeprom FILE: the board's EEPROM loaded at power-on, saved at the end (NULL: blank, not kept) */
    unsigned gdb_port;             /* --gdb PORT: simavr's (an AVR) or armgdb's (an ARM image) gdb stub on 127.0.0.1:PORT, the firmware halted until gdb continues (0: none) */
    const char *arm_elf;           /* --firmware IMAGE.elf: an ARM image on the --board STM32 board (sim/arm) */
    const struct stm32board_spec_s *arm_board_spec; /* that board file, read once by the caller (NULL: run_armboard reads it) */
    int no_skip;                   /* --no-skip: an ARM core sleeps WFI and runs wait loops cycle by cycle (armcore_cfg_t.no_idle_skip) */
    const char *flash_path;        /* --flash FILE: the STM32's flash loaded at power-on, saved at the end (NULL: erased, not kept) */
    const char *watch;             /* --watch NAME[,NAME...]: the firmware's globals on MM_WATCH and in the report (NULL: none) */
    const struct contest_s *contest; /* --contest NAME|FILE: the contest's rules, read once by the caller (NULL: none) */
} run_opts_t;

/* The defaults, then --config's file, --robot's file, --contest's maze
 * geometry and time limit, then the flags that override keys.
 * 0, or -1 after one error line. */
int run_load_config(const run_opts_t *o, simcfg_t *c);
/* One contest; *out gets the result object (NULL if none); with print_text
 * the lap table and summary go to stdout. Returns the exit code. */
int run_one(const run_opts_t *o, const char *maze_path, json_t **out, int print_text);
/* j as one compact JSON line on stdout; 0, or -1. */
int run_json_line(json_t *j);

#endif
