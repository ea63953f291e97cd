/* hal.h - the hardware seam. The firmware talks to the world only through
 * these functions; a backend implements all of them:
 *   hal/sim      links the firmware into the simulator (host, in-process)
 *   hal/arduino  an Arduino library speaking the wire protocol (HIL)
 *   hal/ukmarsbot the UKMARSBOT V1.3 board itself (its README: the motor
 *                command there is a fraction of a reference voltage)
 *
 * A backend also calls the firmware's three entry points (fw_*, below):
 * fw_setup once, fw_tick at HAL_TICK_HZ from a timer interrupt (control:
 * odometry, profiles, motor commands; must return within one tick) and
 * fw_loop repeatedly from the main loop (planning: floods, decisions).
 * fw_loop reads and changes what fw_tick uses (profiles, odometry) only
 * between hal_tick_hold and hal_tick_release.
 *
 * Backend guarantees:
 * - hal_micros: microseconds since start, monotonic, wrapping at 2^32
 *   (71.6 minutes). In hal/sim it is simulation time, never wall clock.
 * - hal_motor_set: command per wheel, -1023..+1023 = -100..+100 % of the
 *   battery voltage, positive drives the robot forward; applied at once.
 * - hal_encoder: signed counts accumulated since start (or the last
 *   hal_encoder_reset), positive forward; 358.32 counts per wheel turn on
 *   the default robot (12 PPR x 29.86 gear).
 * - hal_distance: the latest reading of a ToF sensor in mm and its timeout
 *   flag (nothing within range); each sensor updates about every 30 ms.
 *   seq counts the readings (the sensor's data-ready events), so the
 *   firmware can wait for one taken after a given moment, e.g. after a turn.
 * - hal_log: one text line without the trailing newline, at most
 *   HAL_LOG_MAX bytes; the backend may print, forward or drop it, and must
 *   not block for longer than it takes to queue it.
 * - hal_belief: the mouse's map and position for telemetry; the backend
 *   may copy it or ignore it, and must not keep the pointer.
 * - hal_tick_hold, hal_tick_release (fw_loop only, not nested): fw_tick
 *   does not start in between; a tick due meanwhile starts at the release,
 *   late but not lost, and other interrupts (encoders, serial) go on. An
 *   8-bit MCU loads a float in four byte loads: a tick between them gives
 *   the main loop half an old and half a new value (a profile position
 *   crossing 128 mm, 127.2 -> 128.8, read as 508.8: 0x42FE6666 with the
 *   new top byte 0x43). A backend that calls fw_tick and fw_loop in turn
 *   (hal/sim) does nothing.
 * Sensors of robots other than the paper's (robot file, docs/ROBOTS.md):
 * - hal_ir_count: how many IR reflectance sensors the robot has (its
 *   [ir.*] sections, in the robot file's order); 0 on a robot without.
 * - hal_emitter: switch emitter group `group` (the sensors' `emitter`
 *   key, 0..HAL_EMITTER_GROUPS-1) on (1) or off (0). All start off.
 * - hal_ir_raw: the sensor's phototransistor as a 10-bit ADC sample,
 *   0..1023, taken with the emitters as they are at that moment: read
 *   once dark and once lit and subtract, as real firmware does. In
 *   hal/sim the sample is taken at the call; over the wire (hal/arduino)
 *   it is the newest sample the simulator sent, taken after the latest
 *   hal_emitter it received, and hal_ir_seq counts those samples. A
 *   backend whose own sensor schedule takes both and gives lit minus dark
 *   (hal/ukmarsbot) is built with HAL_IR_LIT_MINUS_DARK defined.
 * - hal_gyro_mdps: the gyro's z rate in millidegrees per second,
 *   counter-clockwise (seen from above) positive, as its output data
 *   rate holds it; 0 on a robot without a gyro (hal_gyro_present 0).
 * - hal_battery_mv: the battery's terminal voltage in millivolts as the
 *   robot's divider and ADC would report it; 0 if the robot has none.
 * The contest:
 * - hal_maze: the maze the contest announces before the start, as a real
 *   contest tells the mouse the goal: its size, the start cell and heading
 *   and the goal rectangle (half-size contests set the goal anywhere).
 *   Returns 1 with *m filled, or 0 if the backend does not know it: the
 *   firmware then assumes a classic contest (16x16, start (0,0) north,
 *   the centre 2x2 goal). Read once, in fw_setup.
 */
#ifndef HAL_H
#define HAL_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* bytes per log line, without the NUL; a backend short of RAM may build
 * with less (the firmware's longest line is 49) */
#ifndef HAL_LOG_MAX
#define HAL_LOG_MAX 80
#endif
#ifndef HAL_TICK_HZ /* control tick, Hz; a build may set it (-DHAL_TICK_HZ=...) */
#ifdef __AVR__
/* 16 MHz AVR: the float control tick takes ~1 ms, the serial link's
 * decoding and interrupts up to ~1 ms more: at 500 Hz 19-31 % of the ticks
 * overran in simavr (mmsim --avr), at 250 Hz none (docs/BENCHMARKS.md) */
#define HAL_TICK_HZ 250
#else
#define HAL_TICK_HZ 1000
#endif
#endif

/* Log text constants. An ATmega328P has 2 KB of SRAM, and avr-gcc copies
 * every string literal into it at reset; these keep them in flash there
 * and are plain strings elsewhere:
 *   HAL_LOG_STR("text")   logs a constant line (hal_log_P on AVR)
 *   HAL_STR("fmt")        a format for hal_snprintf (snprintf_P on AVR)
 * Constant tables likewise: `static const T name[] HAL_FLASH = {...}`,
 * read with hal_flash_u8(&name[i]) / hal_flash_u16(&name[i]). */
#ifdef __AVR__
#include <avr/pgmspace.h>
#define HAL_STR(s) PSTR(s)
#define hal_snprintf snprintf_P
#define HAL_LOG_STR(s) hal_log_P(PSTR(s))
#define HAL_FLASH PROGMEM
#define hal_flash_u8(p) pgm_read_byte(p)
#define hal_flash_u16(p) pgm_read_word(p)
#else
#define HAL_STR(s) (s)
#define hal_snprintf snprintf
#define HAL_LOG_STR(s) hal_log(s)
#define HAL_FLASH
#define hal_flash_u8(p) (*(p))
#define hal_flash_u16(p) (*(p))
#endif

enum { HAL_LEFT = 0, HAL_RIGHT = 1 };
enum { HAL_TOF_LEFT = 0, HAL_TOF_FRONT = 1, HAL_TOF_RIGHT = 2, HAL_TOF_COUNT = 3 };

typedef struct {
    uint16_t mm;     /* distance, millimetres */
    uint8_t timeout; /* 1 = nothing within range (mm is then the range) */
    uint8_t seq;     /* +1 (mod 256) with every new reading of this sensor */
} hal_distance_t;

struct maze_s;

uint32_t hal_micros(void);
void hal_motor_set(int16_t left, int16_t right);
int32_t hal_encoder(uint8_t side);
void hal_encoder_reset(void);
hal_distance_t hal_distance(uint8_t sensor);
void hal_log(const char *line);
#ifdef __AVR__
void hal_log_P(const char *line_in_flash); /* hal_log of a PSTR() line */
#endif
void hal_belief(const struct maze_s *map, uint16_t cell, uint8_t heading, uint8_t state);
void hal_tick_hold(void);
void hal_tick_release(void);

#define HAL_IR_MAX 8          /* IR sensors a robot may have */
#define HAL_EMITTER_GROUPS 4  /* emitter groups */
uint8_t hal_ir_count(void);
void hal_emitter(uint8_t group, uint8_t on);
uint16_t hal_ir_raw(uint8_t sensor);
uint8_t hal_ir_seq(void);
uint8_t hal_gyro_present(void);
int32_t hal_gyro_mdps(void);
uint16_t hal_battery_mv(void);

/* The contest's maze (hal_maze): cells, x east and y north from the
 * south-west cell (0,0); headings 0 north, 1 east, 2 south, 3 west. */
typedef struct {
    uint8_t width, height;         /* cells, 1..the firmware's MAZE_MAX_SIZE */
    uint8_t start_x, start_y;      /* the start cell */
    uint8_t start_heading;         /* 0 north .. 3 west */
    uint8_t goal_x0, goal_y0;      /* the goal rectangle's south-west cell */
    uint8_t goal_x1, goal_y1;      /* and its north-east cell (inclusive) */
} hal_maze_t;
uint8_t hal_maze(hal_maze_t *m);

/* The firmware's entry points, called by the backend. */
void fw_setup(void);
void fw_tick(void);
void fw_loop(void);

#ifdef __cplusplus
}
#endif

#endif
