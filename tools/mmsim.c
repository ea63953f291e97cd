/* mmsim - the headless simulator: one contest on one maze, or a batch.
 *
 * The robot is driven by the mouse's own firmware in-process (hal/sim) by
 * default; `--driver scripted` drives it with a stand-in on the true pose
 * and maze (sim/driver.h), and --serial/--pty/--avr and --mms hand the
 * driving to an MCU or an mms algorithm.
 * Exit codes: 0 ok, 1 goal not reached, 2 bad input, 3 external failure;
 * a batch returns the worst. */
#include <errno.h>
#include <getopt.h>
#include <jansson.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "world/config.h"
#include "contest/driver.h"
#include "hal.h"
#include "hal_sim.h"
#include "link/link.h"
#include "board/pil.h"
#include "link/serial.h"
#include "mouse.h"
#include "maze/solve.h"
#include "maze/mazedir.h"
#include "maze/mazefile.h"
#include "mms/mms.h"
#include "world/sim.h"
#include "telemetry/telem.h"
#include "cli.h"
#include "io/outfile.h"
#include "view/report.h"
#include "view/view.h"

enum { EXIT_OK = 0, EXIT_NOT_REACHED = 1, EXIT_BAD_INPUT = 2, EXIT_EXTERNAL = 3 };

#define STALL_S 5.0 /* no progress for this long while driving = crash stop */

typedef struct {
    const char *config_path;
    uint64_t seed;
    double time_limit_s; /* <= 0: from the config */
    int json, realtime, runs, centre_post, print_config;
    int paper_friction; /* --profile paper */
    int scripted;       /* --driver scripted */
    int verbose;        /* --verbose: firmware log lines on stderr */
    int jobs;
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
} opts_t;

static double wall_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static double ms3(double s) { return round(s * 1000.0) / 1000.0; }

static int load_config(const opts_t *o, simcfg_t *c)
{
    char err[400];
    config_defaults(c);
    if (o->config_path && config_load(c, o->config_path, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return -1;
    }
    if (o->time_limit_s > 0) c->time_limit_s = o->time_limit_s;
    if (o->centre_post >= 0) c->centre_post = o->centre_post;
    if (o->paper_friction) {
        /* the paper's shipped Unity values: static 0.35, dynamic 0.25 */
        c->tyre_mu = 0.35;
        c->tyre_mu_dynamic = 0.25;
    }
    return 0;
}

/* The in-process firmware after a physics step: its control tick at
 * HAL_TICK_HZ (1 kHz: every step), then its background loop. */
static void firmware_step(long *tick_steps, long steps_per_tick)
{
    if (++*tick_steps >= steps_per_tick) {
        *tick_steps = 0;
        fw_tick();
    }
    fw_loop();
}

/* Run one contest; fills *out (a JSON object) and returns the exit code. */
static int run_one(const opts_t *o, const char *maze_path, json_t **out, int print_text)
{
    static maze_t maze;
    static sim_t sim;
    static driver_t drv;
    static telem_t tel;
    static mms_t mms;
    int tel_on = o->telem.url || o->telem.log_path;
    simcfg_t cfg;
    char err[MAZEFILE_ERR_LEN], hash[65];

    *out = NULL;
    if (load_config(o, &cfg) != 0) return EXIT_BAD_INPUT;
    if (mazefile_load(&maze, maze_path, NULL, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return EXIT_BAD_INPUT;
    }
    config_hash(&cfg, hash);
    if (sim_init(&sim, &cfg, &maze, o->seed) != 0) {
        fprintf(stderr, "%s: cannot set up the ODE world\n", maze_path);
        return EXIT_EXTERNAL;
    }
    static link_t lnk;
    static pil_t pil;
    char lerr[400];
    view_opts_t vo = o->view;
    if (o->avr_elf) {
        int lfd;
        drv.done = 0;
        drv.reachable = 1;
        if (pil_open(&pil, o->avr_elf, o->avr_mcu, o->avr_f_cpu, cfg.step_s, &lfd, lerr, sizeof lerr) != 0) {
            fprintf(stderr, "mmsim: %s\n", lerr);
            sim_free(&sim);
            return EXIT_EXTERNAL;
        }
        link_open_fd(&lnk, lfd, "simavr UART0", &o->link, cfg.step_s, (uint16_t)lround(cfg.tof_range_m * 1000.0),
                     (uint32_t)lround(cfg.encoder_ppr * cfg.gear_ratio * 100.0), o->verbose ? stderr : NULL);
    } else if (o->serial) {
        drv.done = 0;
        drv.reachable = 1;
        if (link_open(&lnk, &o->link, cfg.step_s, (uint16_t)lround(cfg.tof_range_m * 1000.0),
                      (uint32_t)lround(cfg.encoder_ppr * cfg.gear_ratio * 100.0), stderr, lerr, sizeof lerr) != 0) {
            fprintf(stderr, "mmsim: %s\n", lerr);
            sim_free(&sim);
            return EXIT_EXTERNAL;
        }
    } else if (o->scripted) {
        driver_init(&drv, &maze, &cfg, o->runs);
    } else { /* the firmware in-process: its own contest, or an mms algorithm's commands */
        drv.done = 0;
        drv.reachable = 1;
        hal_sim_attach(&sim);
        hal_sim_set_log(o->verbose ? stderr : NULL);
        fw_set_maze(&maze);
        fw_set_speed_runs((uint8_t)o->runs);
        fw_setup();
        if (o->mms.command) {
            mouse_cmd_mode();
            if (mms_start(&mms, &o->mms, &maze, err, sizeof err) != 0) {
                fprintf(stderr, "mmsim: %s\n", err);
                hal_sim_attach(NULL);
                sim_free(&sim);
                return EXIT_EXTERNAL;
            }
        }
    }
    telem_opts_t topts = o->telem;
    if (o->serial) topts.link = &lnk; /* MM_LINK in HIL/PIL runs */
    topts.maze_path = maze_path;      /* MM_MAZE names it */
    if (tel_on && telem_open(&tel, &topts, &sim, err, sizeof err) != 0) {
        fprintf(stderr, "mmsim: %s\n", err);
        if (!o->scripted) hal_sim_attach(NULL);
        sim_free(&sim);
        return EXIT_EXTERNAL;
    }

    report_t *rep = o->report ? report_new(&sim) : NULL;
    view_t *view = NULL;
    if (o->gui || o->shot) {
        char verr[400] = "out of memory";
        if (o->serial) { /* the HUD shows the link's port and baud */
            vo.port = lnk.path;
            vo.baud = (long)lnk.o.baud;
        }
        view = view_new(&vo);
        if (view && o->mms.command) view_set_mms(view, mms.color, &mms.text[0][0], sizeof mms.text[0], &mms.was_reset);
        if (!view || view_open(view, o->gui, verr, sizeof verr) != 0) {
            fprintf(stderr, "mmsim: %s\n", verr);
            view_free(view);
            report_free(rep);
            hal_sim_attach(NULL);
            sim_free(&sim);
            return EXIT_EXTERNAL;
        }
    }
    const char *reason = "done";
    double t0 = wall_now(), last_x, last_y, h, progress_s = 0;
    world_pose(sim.world, &last_x, &last_y, &h);
    double hard_stop_s = cfg.time_limit_s + 60.0; /* a lap under way may finish over time, flagged */
    if (!drv.reachable) reason = "unreachable";
    int hil = o->serial; /* an MCU drives: from the start, or since the HUD's Connect */
    /* a build with -DHAL_TICK_HZ=250 ticks every 4th step, as on the AVR */
    long steps_per_tick = lround(1.0 / (HAL_TICK_HZ * cfg.step_s));
    if (steps_per_tick < 1) steps_per_tick = 1;
    long tick_steps = steps_per_tick - 1; /* the first step ticks */
    while (!drv.done) {
        if (hil) { /* HIL: the contest lasts the time limit */
            sim_step(&sim);
            link_step(&lnk, &sim);
            if (tel_on) telem_step(&tel, &sim);
            if (o->avr_elf && pil_step(&pil, lerr, sizeof lerr) != 0) {
                fprintf(stderr, "mmsim: %s: %s\n", o->avr_elf, lerr);
                reason = "avr_stopped";
                break;
            }
            if (lnk.st.stops) { /* the MCU ended the contest (RUN stop) */
                reason = "mcu_stopped";
                break;
            }
            if (sim_time_s(&sim) >= cfg.time_limit_s) {
                reason = "time_limit";
                break;
            }
        } else if (o->mms.command) { /* sim time stands still while the algorithm thinks */
            if (mms_service(&mms, &sim) != MMS_STEP) {
                reason = mms.reason;
                break;
            }
            sim_step(&sim);
            if (tel_on) telem_step(&tel, &sim);
            firmware_step(&tick_steps, steps_per_tick);
        } else if (o->scripted) {
            driver_update(&drv, &sim);
            sim_step(&sim);
            if (tel_on) telem_step(&tel, &sim);
        } else {
            sim_step(&sim);
            if (tel_on) telem_step(&tel, &sim);
            firmware_step(&tick_steps, steps_per_tick);
            uint8_t mode = mouse_status()->mode;
            if (mode == MOUSE_DONE) break;
            if (mode == MOUSE_NO_GOAL) {
                reason = "unreachable";
                break;
            }
            if (mode == MOUSE_CRASHED) {
                reason = "crash_stop";
                break;
            }
        }
        if (rep) report_step(rep, &sim);
        if (o->gui && view_step(view, &sim)) {
            reason = "window_closed";
            break;
        }
        const char *cport;
        long cbaud;
        if (o->gui && view_connect_request(view, &cport, &cbaud)) { /* HUD Connect: the MCU drives from now on */
            link_opts_t lo = o->link;
            lo.device = cport;
            lo.pty = 0;
            lo.baud = (uint32_t)cbaud;
            if (hil) view_set_status(view, "already connected: one link per run");
            else if (link_open(&lnk, &lo, cfg.step_s, (uint16_t)lround(cfg.tof_range_m * 1000.0),
                               (uint32_t)lround(cfg.encoder_ppr * cfg.gear_ratio * 100.0), stderr, lerr, sizeof lerr) != 0)
                view_set_status(view, lerr);
            else {
                hil = 1;
                sim.cmd[0] = sim.cmd[1] = 0;
                if (tel_on) tel.link = &lnk; /* MM_LINK from now on */
                view_set_status(view, "connected: the MCU drives from now on");
            }
        }
        if (o->shot && sim_time_s(&sim) >= o->shot_at_s) {
            reason = "screenshot";
            break;
        }
        double t = sim_time_s(&sim), x, y;
        if (sim.race.over_time && !sim.race.in_run) {
            reason = "time_limit";
            break;
        }
        if (t > hard_stop_s) {
            reason = "time_limit";
            break;
        }
        if (sim.step % 100 == 0 && !hil && !o->mms.command) { /* a HIL robot may wait for its MCU; mms: the firmware's own stall check */
            world_pose(sim.world, &x, &y, &h);
            if (hypot(x - last_x, y - last_y) > 0.01) {
                last_x = x;
                last_y = y;
                progress_s = t;
            } else if (t - progress_s > STALL_S) {
                reason = "crash_stop"; /* stuck: motors off, reported */
                sim.cmd[0] = sim.cmd[1] = 0;
                break;
            }
        }
        if (o->realtime) {
            double ahead = t - (wall_now() - t0);
            if (ahead > 0.002) {
                struct timespec ts = { 0, (long)(ahead * 1e9) };
                nanosleep(&ts, NULL);
            }
        }
    }
    if (o->mms.command) {
        mms_stop(&mms);
        if (mms.message[0]) fprintf(stderr, "%s\n", mms.message);
    }
    int tel_rc = 0;
    if (tel_on) {
        telem_finish(&tel, &sim);
        if ((tel_rc = telem_close(&tel, err, sizeof err)) != 0) fprintf(stderr, "mmsim: %s\n", err);
    }
    int view_failed = 0;
    if (view) {
        char verr[600];
        if (o->shot && view_screenshot(view, &sim, o->shot, verr, sizeof verr) != 0) {
            fprintf(stderr, "mmsim: %s\n", verr);
            view_failed = 1;
        }
        if (o->gui) view_hold(view, &sim);
        view_free(view);
    }
    double wall = wall_now() - t0, t = sim_time_s(&sim), x, y;
    world_pose(sim.world, &x, &y, &h);
    const race_t *r = &sim.race;

    json_t *laps = json_array();
    for (int i = 0; i < r->nlaps; i++)
        json_array_append_new(laps, json_pack("{s:i, s:f, s:f, s:f}", "lap", i + 1, "start_s", ms3(r->laps[i].start_s),
                                              "end_s", ms3(r->laps[i].end_s),
                                              "run_s", ms3(r->laps[i].end_s - r->laps[i].start_s)));
    json_t *o_json = json_pack("{s:s, s:I, s:f, s:f, s:f, s:o}", "maze", maze_path, "seed", (json_int_t)o->seed,
                               "sim_time_s", ms3(t), "wall_time_s", ms3(wall), "real_time_factor",
                               wall > 0 ? round(t / wall * 10) / 10 : 0.0, "laps", laps);
    json_object_set_new(o_json, "first_run_s",
                        r->nlaps ? json_real(ms3(r->laps[0].end_s - r->laps[0].start_s)) : json_null());
    json_object_set_new(o_json, "best_run_s",
                        r->best >= 0 ? json_real(ms3(r->laps[r->best].end_s - r->laps[r->best].start_s)) : json_null());
    json_object_set_new(o_json, "reached_goal", json_boolean(r->nlaps > 0));
    json_object_set_new(o_json, "collisions", json_integer(world_collisions(sim.world)));
    json_object_set_new(o_json, "final_pose", json_pack("{s:f, s:f, s:f}", "x_m", round(x * 1e6) / 1e6, "y_m",
                                                        round(y * 1e6) / 1e6, "heading_rad", round(h * 1e6) / 1e6));
    json_object_set_new(o_json, "exit_reason", json_string(reason));
    json_object_set_new(o_json, "config_hash", json_string(hash));
    const char *driver_name = o->serial ? "serial" : o->scripted ? "scripted" : o->mms.command ? "mms" : "firmware";
    if (o->mms.command) {
        json_t *mj = mms_json(&mms);
        json_object_set_new(mj, "wall_contacts", json_integer(world_collisions(sim.world))); /* = collisions */
        json_object_set_new(o_json, "mms", mj);
    }
    json_object_set_new(o_json, "driver", json_string(driver_name));
    if (hil) {
        json_object_set_new(o_json, "link", link_json(&lnk));
        link_close(&lnk);
        if (o->avr_elf) {
            uint32_t stack_max, free_min;
            pil_stack(&pil, &stack_max, &free_min);
            json_object_set_new(o_json, "avr", json_pack("{s:s, s:s, s:I, s:I, s:I, s:I, s:I, s:I}", "elf", o->avr_elf,
                                                         "mcu", pil.mcu, "f_cpu_hz", (json_int_t)pil.f_cpu, "cycles",
                                                         (json_int_t)pil.cycles, "uart_bytes_in",
                                                         (json_int_t)pil.bytes_in, "uart_bytes_out",
                                                         (json_int_t)pil.bytes_out, "stack_max_bytes",
                                                         (json_int_t)stack_max, "sram_free_min_bytes",
                                                         (json_int_t)free_min));
            pil_close(&pil);
        }
    }
    int report_failed = 0;
    if (rep) {
        char title[300], rerr[600];
        snprintf(title, sizeof title, "%s  %ux%u  seed %llu  %s driver  exit: %s", maze_path, maze.width, maze.height,
                 (unsigned long long)o->seed, driver_name, reason);
        if (o->mms.command) report_set_cells(rep, mms.color, &mms.text[0][0], sizeof mms.text[0]);
        if (report_write(rep, &sim, o->scripted || o->serial ? NULL : mouse_map(), o->report, title, rerr, sizeof rerr) != 0) {
            fprintf(stderr, "%s\n", rerr);
            report_failed = 1;
        }
        report_free(rep);
    }
    if (!o->scripted && !o->serial) {
        /* the path the mouse would run: best through known-open walls */
        static solve_path_t truth, known;
        int ok_truth = solve_best(&maze, 0, &truth) == 0, ok_known = solve_best(mouse_map(), 0, &known) == 0;
        uint16_t proven = mouse_proven_at_step();
        if (!o->mms.command) { /* the firmware's own search (an mms algorithm searches by itself) */
            json_object_set_new(o_json, "proven_at_step", proven == 0xFFFFu ? json_null() : json_integer(proven));
            json_object_set_new(o_json, "final_path_optimal", json_boolean(ok_truth && ok_known && proven != 0xFFFFu &&
                                                                           known.cost == truth.cost));
        }
        hal_sim_attach(NULL);
    }

    if (print_text) {
        if (o->serial)
            printf("%s: %ux%u, seed %llu, MCU over %s (%s, %u baud): sent %llu B (%.0f %%), received %llu B (%.0f %%), "
                   "dropped %llu messages, %u decode errors, %u silences, %u disconnects\n",
                   maze_path, maze.width, maze.height, (unsigned long long)o->seed, lnk.path,
                   o->link.protocol == LINK_COMPAT ? "compat" : "framed", (unsigned)lnk.o.baud,
                   (unsigned long long)lnk.st.tx_bytes, link_util_tx(&lnk) * 100, (unsigned long long)lnk.st.rx_bytes,
                   link_util_rx(&lnk) * 100, (unsigned long long)lnk.st.tx_dropped,
                   (unsigned)wire_stats_errors(o->link.protocol == LINK_COMPAT ? &lnk.crx.stats : &lnk.dec.stats),
                   (unsigned)lnk.st.silences, (unsigned)lnk.st.disconnects);
        else if (o->mms.command)
            printf("%s: %ux%u, seed %llu, mms algorithm '%s' (%s walls), score %g\n", maze_path, maze.width, maze.height,
                   (unsigned long long)o->seed, o->mms.command, o->mms.ideal_walls ? "ideal" : "sensed",
                   (double)mms_stats_score(&mms.stats));
        else if (o->scripted)
            printf("%s: %ux%u, seed %llu, scripted driver, %d run%s\n", maze_path, maze.width, maze.height,
                   (unsigned long long)o->seed, o->runs, o->runs == 1 ? "" : "s");
        else
            printf("%s: %ux%u, seed %llu, firmware\n", maze_path, maze.width, maze.height, (unsigned long long)o->seed);
        race_print_table(r, stdout);
        printf("sim time %.3f s, wall time %.3f s (%.0fx real time), collisions %u, exit: %s\n", t, wall,
               wall > 0 ? t / wall : 0.0, world_collisions(sim.world), reason);
    }
    sim_free(&sim);
    *out = o_json;
    if (tel_rc) return EXIT_EXTERNAL;
    if (report_failed || view_failed) return EXIT_EXTERNAL;
    if (o->shot) return EXIT_OK; /* the picture was the point */
    if (!strcmp(reason, "avr_stopped")) return EXIT_EXTERNAL;
    if (o->mms.command) { /* the algorithm's failure is an external one; else: was the goal reached */
        if (mms_failed(&mms)) return EXIT_EXTERNAL;
        return r->nlaps > 0 && (!strcmp(reason, "mms_exited") || !strcmp(reason, "time_limit")) ? EXIT_OK : EXIT_NOT_REACHED;
    }
    return r->nlaps > 0 && (!strcmp(reason, "done") || !strcmp(reason, "mcu_stopped")) ? EXIT_OK : EXIT_NOT_REACHED;
}

static int print_json_line(json_t *j)
{
    char *s = json_dumps(j, JSON_COMPACT | JSON_ENSURE_ASCII | JSON_REAL_PRECISION(10));
    if (!s) return -1;
    puts(s);
    fflush(stdout);
    free(s);
    return 0;
}

/* All a child wrote to its pipe, until end of file (NUL-terminated). */
static char *read_all(int fd)
{
    size_t len = 0, cap = 4096;
    char *buf = malloc(cap);
    for (;;) {
        if (!buf) return NULL;
        if (len + 1 >= cap) {
            char *b = realloc(buf, cap *= 2);
            if (!b) { free(buf); return NULL; }
            buf = b;
        }
        ssize_t k = read(fd, buf + len, cap - 1 - len);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) break;
        len += (size_t)k;
    }
    buf[len] = '\0';
    return buf;
}

/* The line of a maze whose child printed no JSON (it died, or the maze
 * file was bad: its error line is on stderr): one line per maze all the same. */
static char *failed_line(const char *maze, int status)
{
    json_t *j = json_object();
    json_object_set_new(j, "maze", json_string(maze));
    json_object_set_new(j, "exit_reason", json_string("no_result"));
    if (WIFSIGNALED(status)) json_object_set_new(j, "signal", json_integer(WTERMSIG(status)));
    else json_object_set_new(j, "exit_code", json_integer(WIFEXITED(status) ? WEXITSTATUS(status) : -1));
    char *s = json_dumps(j, JSON_COMPACT | JSON_ENSURE_ASCII);
    json_decref(j);
    if (!s) return NULL;
    char *line = malloc(strlen(s) + 2);
    if (line) sprintf(line, "%s\n", s);
    free(s);
    return line;
}

/* Every *.txt in dir, one child process per maze, `jobs` at a time; one JSON
 * line per maze on stdout in input order; returns the worst exit code.
 * A reaped child is matched among the running jobs only: process ids are
 * reused (pid_max 32768 here; a 481-maze batch beside a busy machine wraps
 * it, and matching an earlier, finished job lost two lines). */
static int run_batch(const opts_t *o, const char *dir)
{
    char **names;
    long nn = mazedir_list_or_report(dir, &names);
    if (nn < 0) return EXIT_BAD_INPUT;
    size_t n = (size_t)nn;
    int worst = EXIT_OK;
    size_t next = 0, done = 0, printed = 0;
    pid_t *pid = calloc(n, sizeof *pid);     /* 0: not started, or reaped */
    int *fd = calloc(n, sizeof *fd);
    char **text = calloc(n, sizeof *text);
    int running = 0;
    if (!pid || !fd || !text) {
        fprintf(stderr, "mmsim: out of memory\n");
        worst = EXIT_EXTERNAL;
        goto out;
    }
    while (done < n) {
        while (running < o->jobs && next < n) {
            int p[2];
            if (pipe(p) != 0) {
                fprintf(stderr, "mmsim: pipe: %s\n", strerror(errno));
                worst = EXIT_EXTERNAL;
                goto out;
            }
            fflush(stdout);
            pid_t c = fork();
            if (c < 0) {
                fprintf(stderr, "mmsim: fork: %s\n", strerror(errno));
                close(p[0]);
                close(p[1]);
                worst = EXIT_EXTERNAL;
                goto out;
            }
            if (c == 0) {
                close(p[0]);
                for (size_t i = 0; i < next; i++) /* the other jobs' pipes are not this child's */
                    if (pid[i]) close(fd[i]);
                if (dup2(p[1], STDOUT_FILENO) < 0) _exit(EXIT_EXTERNAL);
                json_t *j;
                int rc = run_one(o, names[next], &j, 0);
                if (j) print_json_line(j);
                fflush(stdout);
                _exit(rc);
            }
            close(p[1]);
            pid[next] = c;
            fd[next] = p[0];
            next++;
            running++;
        }
        /* any job that ended; matched among the running ones only. Its
         * output (one JSON line, far below the pipe's 64 KB, so a child
         * never blocks on it) is read to the end after it is reaped. */
        int status = 0;
        pid_t c = wait(&status);
        if (c < 0) {
            if (errno == EINTR) continue;
            fprintf(stderr, "mmsim: wait: %s\n", strerror(errno));
            worst = EXIT_EXTERNAL;
            goto out;
        }
        size_t i = 0;
        while (i < next && pid[i] != c) i++;
        if (i == next) continue; /* not one of the running jobs */
        char *out = read_all(fd[i]);
        close(fd[i]);
        pid[i] = 0;
        running--;
        done++;
        int code = WIFEXITED(status) ? WEXITSTATUS(status) : EXIT_EXTERNAL;
        if (code > worst) worst = code;
        if (!out || !strchr(out, '{')) { /* no JSON from the child */
            free(out);
            out = failed_line(names[i], status);
        }
        text[i] = out ? out : strdup("");
        fprintf(stderr, "\r[%zu/%zu] %-60.60s", done, n, names[i]);
        while (printed < n && text[printed]) { /* results in input order */
            fputs(text[printed], stdout);
            printed++;
        }
    }
    fputc('\n', stderr);
out:
    fflush(stdout);
    for (size_t i = 0; pid && fd && i < next; i++)
        if (pid[i]) { /* only after a failure above: end the jobs still running */
            kill(pid[i], SIGKILL);
            close(fd[i]);
            waitpid(pid[i], NULL, 0);
        }
    for (size_t i = 0; text && i < n; i++) free(text[i]);
    mazedir_free(names, nn);
    free(text);
    free(pid);
    free(fd);
    return worst;
}

static void usage(FILE *out)
{
    fputs("usage: mmsim --maze FILE [--config FILE] [--seed N] [--time-limit S] [--runs N]\n"
          "             [--centre-post on|off] [--profile default|paper] [--driver firmware|scripted]\n"
          "             [--json] [--realtime] [--verbose] [--report FILE.png]\n"
          "             (--runs: speed runs after the search, default 3; scripted: runs to the goal)\n"
          "             [--lcm[=URL]] [--lcm-log FILE] [--lcm-rate HZ]   (LCM telemetry, sim/telem.h)\n"
          "             [--gui [--speed 1..64]] [--screenshot FILE.png [--at SECONDS]]\n"
          "             [--camera 1|2|3] [--size WxH]   (viewer)\n"
          "       mmsim --maze FILE --serial DEV|--port DEV|--pty [--baud N] [--protocol framed|compat]\n"
          "             [--silence-ms N]   (hardware in the loop: an MCU drives over a serial link,\n"
          "             in real time; --pty creates a pseudo-terminal and prints its path; docs/PROTOCOL.md)\n"
          "       mmsim --maze FILE --avr ELF [--mcu NAME] [--f-cpu HZ] [--baud N] [--protocol P]\n"
          "             (processor in the loop: the AVR image runs in simavr, in lockstep)\n"
          "       mmsim --maze FILE --mms COMMAND [--mms-ideal-walls] [--mms-timeout-ms N] [--mms-reset-at S]\n"
          "             (an mms algorithm drives the robot through the mms text API, docs/MMS.md)\n"
          "       mmsim --batch DIR [--jobs N] [options as above]   (one JSON line per maze)\n"
          "       mmsim --print-config [--config FILE]\n"
          "Exit codes: 0 ok, 1 goal not reached, 2 bad input, 3 external failure.\n",
          out);
}

static int bad(const char *fmt, const char *arg) { return cli_bad("mmsim", fmt, arg); }
static int num(const char *opt, const char *s, double lo, double hi, double *out)
{
    return cli_number("mmsim", opt, s, lo, hi, out);
}

int main(int argc, char **argv)
{
    static const struct option opts[] = {
        { "maze", required_argument, 0, 'm' },   { "config", required_argument, 0, 'c' },
        { "seed", required_argument, 0, 's' },   { "time-limit", required_argument, 0, 't' },
        { "json", no_argument, 0, 'j' },         { "realtime", no_argument, 0, 'r' },
        { "runs", required_argument, 0, 'n' },   { "centre-post", required_argument, 0, 'p' },
        { "print-config", no_argument, 0, 'P' }, { "batch", required_argument, 0, 'b' },
        { "jobs", required_argument, 0, 'J' },   { "help", no_argument, 0, 'h' },
        { "profile", required_argument, 0, 'F' }, { "driver", required_argument, 0, 'D' },
        { "verbose", no_argument, 0, 'v' },
        { "lcm", optional_argument, 0, 'L' },    { "lcm-log", required_argument, 0, 'G' },
        { "lcm-rate", required_argument, 0, 'R' },
        { "report", required_argument, 0, 1001 },
        { "gui", no_argument, 0, 1002 },          { "screenshot", required_argument, 0, 'S' },
        { "at", required_argument, 0, 'A' },     { "camera", required_argument, 0, 'C' },
        { "size", required_argument, 0, 'Z' },   { "speed", required_argument, 0, 'X' },
        { "port", required_argument, 0, 'T' },   { "baud", required_argument, 0, 'B' },
        { "serial", required_argument, 0, 'T' }, { "pty", no_argument, 0, 2001 },
        { "protocol", required_argument, 0, 2002 }, { "silence-ms", required_argument, 0, 2003 },
        { "avr", required_argument, 0, 2004 },   { "mcu", required_argument, 0, 2005 },
        { "f-cpu", required_argument, 0, 2006 },
        { "mms", required_argument, 0, 3001 },   { "mms-ideal-walls", no_argument, 0, 3002 },
        { "mms-timeout-ms", required_argument, 0, 3003 }, { "mms-reset-at", required_argument, 0, 3004 },
        { 0, 0, 0, 0 },
    };
    opts_t o = { /* the mouse's own firmware by default, 3 speed runs after the search */
        .seed = 1, .runs = 3, .centre_post = -1, .scripted = 0, .jobs = 1,
        .view = { .width = 1024, .height = 720, .speed = 1, .camera = 1, .port = "", .baud = 115200 },
        .link = { .protocol = LINK_FRAMED },
        .mms = { .timeout_ms = 5000, .reset_at_s = -1 },
    };
    const char *maze = NULL, *batch = NULL;
    double v;
    int c, link_flags = 0, mms_flags = 0, driver_given = 0;
    opterr = 0;
    while ((c = getopt_long(argc, argv, "", opts, NULL)) != -1) {
        switch (c) {
        case 'm': maze = optarg; break;
        case 'c': o.config_path = optarg; break;
        case 's':
            if (num("--seed", optarg, 0, 9007199254740992.0, &v)) return EXIT_BAD_INPUT;
            if (v != floor(v)) return bad("--seed: expected a whole number, got '%s'", optarg);
            o.seed = (uint64_t)v;
            break;
        case 't':
            if (num("--time-limit", optarg, 1, 86400, &o.time_limit_s)) return EXIT_BAD_INPUT;
            break;
        case 'n':
            if (num("--runs", optarg, 1, 64, &v) || v != floor(v)) return bad("--runs: expected 1 to 64, got '%s'", optarg);
            o.runs = (int)v;
            break;
        case 'J':
            if (num("--jobs", optarg, 1, 256, &v) || v != floor(v)) return bad("--jobs: expected 1 to 256, got '%s'", optarg);
            o.jobs = (int)v;
            break;
        case 'p':
            if (!strcmp(optarg, "on")) o.centre_post = 1;
            else if (!strcmp(optarg, "off")) o.centre_post = 0;
            else return bad("--centre-post: expected on or off, got '%s'", optarg);
            break;
        case 'F':
            if (!strcmp(optarg, "paper")) o.paper_friction = 1;
            else if (strcmp(optarg, "default")) return bad("--profile: expected default or paper, got '%s'", optarg);
            break;
        case 'D':
            if (strcmp(optarg, "scripted") && strcmp(optarg, "firmware"))
                return bad("--driver: expected firmware or scripted, got '%s'", optarg);
            o.scripted = !strcmp(optarg, "scripted");
            driver_given = 1;
            break;
        case 'v': o.verbose = 1; break;
        case 'L':
            o.telem.url = optarg ? optarg : "";
            if (optarg && !strstr(optarg, "://")) return bad("--lcm: expected an LCM URL like udpm://239.255.76.67:7667?ttl=0, got '%s'", optarg);
            break;
        case 'G':
            if (!*optarg) return bad("%s", "--lcm-log: expected a file name");
            o.telem.log_path = optarg;
            break;
        case 'R':
            if (num("--lcm-rate", optarg, 1, 1000, &o.telem.rate_hz)) return EXIT_BAD_INPUT;
            break;
        case 1001: o.report = optarg; break;
        case 1002: o.gui = 1; break;
        case 'S': o.shot = optarg; break;
        case 'A':
            if (num("--at", optarg, 0, 86400, &o.shot_at_s)) return EXIT_BAD_INPUT;
            break;
        case 'C':
            if (cli_view_option("mmsim", "camera", optarg, &o.view)) return EXIT_BAD_INPUT;
            break;
        case 'X':
            if (cli_view_option("mmsim", "speed", optarg, &o.view)) return EXIT_BAD_INPUT;
            break;
        case 'Z':
            if (cli_view_option("mmsim", "size", optarg, &o.view)) return EXIT_BAD_INPUT;
            break;
        case 'T': /* --serial DEV or --port DEV (the viewer shows it) */
            o.link.device = optarg;
            o.view.port = optarg;
            break;
        case 'B': /* the link's rate, shown by the viewer */
            if (num("--baud", optarg, 50, SERIAL_BAUD_MAX, &v)) return EXIT_BAD_INPUT;
            if (v != floor(v)) return bad("--baud: expected a whole number of bits/s, got '%s'", optarg);
            o.link.baud = (uint32_t)v;
            o.view.baud = (long)v;
            break;
        case 2001: o.link.pty = 1; break;
        case 2002:
            if ((o.link.protocol = link_parse_protocol(optarg)) < 0) return bad("--protocol: expected framed or compat, got '%s'", optarg);
            link_flags++;
            break;
        case 2003:
            if (num("--silence-ms", optarg, 1, 60000, &v)) return EXIT_BAD_INPUT;
            o.link.silence_s = v / 1000.0;
            link_flags++;
            break;
        case 2004: o.avr_elf = optarg; break;
        case 2005: o.avr_mcu = optarg; break;
        case 2006:
            if (num("--f-cpu", optarg, 1000, 100e6, &v)) return EXIT_BAD_INPUT;
            o.avr_f_cpu = (uint32_t)v;
            break;
        case 3001:
            if (!*optarg) return bad("%s", "--mms: expected a command, e.g. --mms 'python3 main.py'");
            o.mms.command = optarg;
            break;
        case 3002: o.mms.ideal_walls = 1; mms_flags++; break;
        case 3003:
            if (num("--mms-timeout-ms", optarg, 1, 3600000, &v)) return EXIT_BAD_INPUT;
            o.mms.timeout_ms = (int)v;
            mms_flags++;
            break;
        case 3004:
            if (num("--mms-reset-at", optarg, 0, 86400, &o.mms.reset_at_s)) return EXIT_BAD_INPUT;
            mms_flags++;
            break;
        case 'j': o.json = 1; break;
        case 'r': o.realtime = 1; break;
        case 'P': o.print_config = 1; break;
        case 'b': batch = optarg; break;
        case 'h': usage(stdout); return EXIT_OK;
        default: return bad("unknown option or missing value: '%s'", argv[optind - 1]);
        }
    }
    if (optind != argc) return bad("unexpected argument '%s'", argv[optind]);
    o.serial = o.link.device || o.link.pty || o.avr_elf;
    if (!!o.link.device + o.link.pty + !!o.avr_elf > 1) return bad("%s", "--serial/--port, --pty and --avr exclude each other");
    if (!o.serial && link_flags) return bad("%s", "--protocol and --silence-ms need --serial DEV, --pty or --avr ELF");
    if (!o.avr_elf && (o.avr_mcu || o.avr_f_cpu)) return bad("%s", "--mcu and --f-cpu need --avr ELF");
    if (!o.mms.command && mms_flags) return bad("%s", "--mms-ideal-walls, --mms-timeout-ms and --mms-reset-at need --mms COMMAND");
    if (o.mms.command && o.verbose) o.mms.trace = stderr; /* --verbose: the mms dialogue too */
    if (o.mms.command && !driver_given) o.scripted = 0; /* the firmware's motion layer runs the moves */
    if (o.mms.command && (o.serial || o.scripted || batch))
        return bad("%s", "--mms drives the firmware of one run: not with --serial/--pty/--avr, --driver scripted or --batch");
    if (o.serial && batch) return bad("%s", "--serial/--pty/--avr run one maze, not --batch");
    if (o.serial && !o.avr_elf) o.realtime = 1; /* a real MCU runs in real time; simavr in lockstep */
    if (o.print_config) {
        simcfg_t cfg;
        if (load_config(&o, &cfg) != 0) return EXIT_BAD_INPUT;
        config_print(&cfg, stdout);
        return EXIT_OK;
    }
    if (batch && (o.telem.url || o.telem.log_path)) return bad("%s", "--lcm and --lcm-log work on one maze, not with --batch");
    if (batch && (o.report || o.gui || o.shot)) return bad("%s", "--report, --gui and --screenshot need --maze (one run), not --batch");
    if (o.gui && o.shot) return bad("%s", "--gui and --screenshot: one at a time");
    if (batch) return run_batch(&o, batch);
    if (!maze) return bad("%s", "--maze FILE is required");
    const char *outs[2][2] = { { "--report", o.report }, { "--screenshot", o.shot } };
    for (int i = 0; i < 2; i++) { /* fail now, not after a ten-minute contest */
        char perr[600];
        outfile_t probe;
        if (!outs[i][1]) continue;
        if (outfile_open(&probe, outs[i][1], perr, sizeof perr) != 0) {
            fprintf(stderr, "mmsim: %s: %s\n", outs[i][0], perr);
            return EXIT_BAD_INPUT;
        }
        outfile_abort(&probe);
    }
    json_t *j;
    int rc = run_one(&o, maze, &j, !o.json);
    if (j && o.json && print_json_line(j) != 0) rc = EXIT_EXTERNAL;
    json_decref(j);
    return rc;
}
