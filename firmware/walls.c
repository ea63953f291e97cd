/* walls.c - ToF or IR readings as distances (walls.h). */
#include "walls.h"

#include <math.h>

#include "explore.h"
#include "robot_config.h"
#include "walls_ir.h"

/* the forward pair's sum in 1/64 of its calibrated sum, falling, and the
 * distance to the wall ahead at each (robot_config: RC_IR_FRONT_CURVE_*) */
static const uint16_t curve_ratio64[] HAL_FLASH = RC_IR_FRONT_CURVE_RATIO64;
static const uint8_t curve_mm[] HAL_FLASH = RC_IR_FRONT_CURVE_MM;
#define CURVE_POINTS (sizeof curve_mm / sizeof curve_mm[0])

/* the distance for a sum of ratio64 / 64 of the calibrated one: linear
 * between the curve's points; timeout past its far end */
static hal_distance_t front_mm(uint32_t ratio64)
{
    hal_distance_t d = { hal_flash_u8(&curve_mm[0]), 0, 0 };
    if (ratio64 >= hal_flash_u16(&curve_ratio64[0])) return d; /* nearer than the curve: its nearest point */
    for (uint8_t i = 1; i < CURVE_POINTS; i++) {
        uint16_t r1 = hal_flash_u16(&curve_ratio64[i]);
        if (ratio64 < r1) continue;
        uint16_t r0 = hal_flash_u16(&curve_ratio64[i - 1]);
        uint8_t m0 = hal_flash_u8(&curve_mm[i - 1]), m1 = hal_flash_u8(&curve_mm[i]);
        d.mm = (uint16_t)(m1 - (uint32_t)(m1 - m0) * (ratio64 - r1) / (uint16_t)(r0 - r1));
        return d;
    }
    d.mm = hal_flash_u8(&curve_mm[CURVE_POINTS - 1]);
    d.timeout = 1;
    return d;
}

void walls_setup(void)
{
    if (!RC_WALLS_IR || !hal_ir_count()) return;
    for (uint8_t g = 0; g < HAL_EMITTER_GROUPS; g++) hal_emitter(g, 1);
}

#ifdef HAL_IR_LIT_MINUS_DARK
/* the backend's hal_ir_raw is already lit minus dark (hal.h): its sensor
 * schedule samples each sensor dark and lit every tick (hal/ukmarsbot) */
#define ir_reading hal_ir_raw
#else
/* a backend that samples at the call with the emitters as they are
 * (hal/sim): a dark sample with every emitter off, then a lit one, and
 * their difference, as the board's schedule takes them. Over the wire
 * (hal/arduino) a sample comes ticks after its hal_emitter, so both
 * would be the same frame: this reading is for hal/sim and hal/ukmarsbot. */
static uint16_t ir_reading(uint8_t sensor)
{
    for (uint8_t g = 0; g < HAL_EMITTER_GROUPS; g++) hal_emitter(g, 0);
    uint16_t dark = hal_ir_raw(sensor);
    for (uint8_t g = 0; g < HAL_EMITTER_GROUPS; g++) hal_emitter(g, 1);
    uint16_t lit = hal_ir_raw(sensor);
    return lit > dark ? (uint16_t)(lit - dark) : 0u;
}
#endif

hal_distance_t walls_distance(uint8_t sensor)
{
    if (!RC_WALLS_IR || !hal_ir_count()) return hal_distance(sensor);
    hal_distance_t d = { 0, 1, hal_ir_seq() };
    const walls_ir_cal_t *c = walls_ir_cal();
    if (walls_ir_sensor(WALLS_IR_LEFT) == 255) return d;
    if (sensor == HAL_TOF_FRONT) {
        uint32_t sum = (uint32_t)ir_reading(walls_ir_sensor(WALLS_IR_FRONT_L)) + ir_reading(walls_ir_sensor(WALLS_IR_FRONT_R));
        uint32_t ref = (uint32_t)c->front_ref[0] + c->front_ref[1];
        hal_distance_t f = front_mm(sum * 64u / (ref ? ref : 1u));
        f.seq = d.seq;
        return f;
    }
    uint8_t side = sensor == HAL_TOF_RIGHT;
    uint16_t raw = ir_reading(walls_ir_sensor(side ? WALLS_IR_RIGHT : WALLS_IR_LEFT)), ref = c->side_ref[side];
    if ((uint32_t)raw * 100u < (uint32_t)ref * c->side_pct || !raw) return d; /* no wall */
    d.mm = (uint16_t)(RC_SIDE_WALL_MM * sqrtf((float)ref / (float)raw) + 0.5f);
    d.timeout = 0;
    return d;
}

/* ---- the wall decision ---- */
static uint8_t front_wall(hal_distance_t f, float limit_mm) { return !f.timeout && f.mm < limit_mm ? EXPLORE_WALL_FRONT : 0u; }

uint8_t walls_ahead(float front_limit_mm) { return front_wall(walls_distance(HAL_TOF_FRONT), front_limit_mm); }

uint8_t walls_around(float front_limit_mm)
{
    uint8_t w = 0;
    hal_distance_t l = walls_distance(HAL_TOF_LEFT), f = walls_distance(HAL_TOF_FRONT), r = walls_distance(HAL_TOF_RIGHT);
    w |= front_wall(f, front_limit_mm);
    if (!l.timeout && l.mm < RC_SIDE_THRESHOLD_MM) w |= EXPLORE_WALL_LEFT;
    if (!r.timeout && r.mm < RC_SIDE_THRESHOLD_MM) w |= EXPLORE_WALL_RIGHT;
    return w;
}
