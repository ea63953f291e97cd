// IrProbe - a test sketch for test/cli/cli_pil.sh: the runner (mm_mouse_begin)
// with a stand-in firmware that only calls hal.h's sensor functions of
// robots other than the paper's, from fw_tick as real firmware would. It
// logs what it got so the test can compare it with what the simulator
// reports sending (mmsim --verbose: "IR seq N, emitters 0xM: ..." and
// "robot for the MCU: ..."):
//   "IrProbe: ir N, gyro P G mdps, battery B mV"  once, after 200 ms
//   "ir SEQ MASK: v0 v1 ..."   per sample, MASK the groups it lit
//   "IrProbe: no sample, ir N raw0 R"  no IR frame within 0.5 s (compat)
// Six emitter patterns, then the mouse is "done": the runner sends RUN stop.
// Built framed (1 Mbaud) and, with -DIRPROBE_COMPAT, compat (115200): a
// simulator that never sends IR, gyro or battery.
#include <Micromouse.h>
#include <stdio.h>
#include "hal.h"
extern "C" { // the firmware's headers are plain C
#include "mouse.h"
}

static mouse_status_t status;          // mode MOUSE_DONE ends the run
static const uint8_t PATTERN[] = { 0x1, 0x0, 0x6, 0xF, 0x0, 0x8 };
static uint16_t ticks, waited;
static uint8_t step, mask, seq0, waiting, pause;

extern "C" const mouse_status_t *mouse_status(void) { return &status; }
extern "C" void fw_setup(void) { status.mode = 0; }
extern "C" void fw_loop(void) {}

static void log_sample()
{
    char line[HAL_LOG_MAX + 1];
    int n = hal_snprintf(line, sizeof line, HAL_STR("ir %u %u:"), (unsigned)hal_ir_seq(), (unsigned)mask);
    for (uint8_t i = 0; i < hal_ir_count() && n < (int)sizeof line; i++)
        n += hal_snprintf(line + n, sizeof line - n, HAL_STR(" %u"), (unsigned)hal_ir_raw(i));
    hal_log(line);
}

static void report()
{
    char line[HAL_LOG_MAX + 1];
    hal_snprintf(line, sizeof line, HAL_STR("IrProbe: ir %u, gyro %u %ld mdps, battery %u mV"), (unsigned)hal_ir_count(),
                 (unsigned)hal_gyro_present(), (long)hal_gyro_mdps(), (unsigned)hal_battery_mv());
    hal_log(line);
}

extern "C" void fw_tick(void)
{
    if (++ticks < 50 || status.mode == MOUSE_DONE) return;
    if (ticks == 50) return report();
    if (waiting) {
        if (hal_ir_seq() != seq0) {
            waiting = 0;
            pause = 10;
            log_sample();
        } else if (++waited >= 125) {
            char line[48];
            waiting = 0;
            hal_snprintf(line, sizeof line, HAL_STR("IrProbe: no sample, ir %u raw0 %u"), (unsigned)hal_ir_count(),
                         (unsigned)hal_ir_raw(0));
            hal_log(line);
        }
        return;
    }
    if (pause) {
        pause--;
        return;
    }
    if (step == sizeof PATTERN) {
        status.mode = MOUSE_DONE;
        return;
    }
    mask = PATTERN[step++];
    for (uint8_t g = 0; g < HAL_EMITTER_GROUPS; g++) hal_emitter(g, (mask >> g) & 1);
    seq0 = hal_ir_seq();
    waited = 0;
    waiting = 1;
}

void setup()
{
#ifdef IRPROBE_COMPAT
    Serial.begin(115200);
    mm_mouse_begin(Serial, MM_COMPAT);
#else
    Serial.begin(1000000);
    mm_mouse_begin(Serial, MM_FRAMED);
#endif
}

void loop() { mm_mouse_loop(); }
