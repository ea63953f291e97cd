/* walls_ir.c - IR wall detection against a calibration (walls_ir.h). */
#include "walls_ir.h"

#include "hal.h"

/* ORION's calibration (mazerunner-core config-robot-orion.h, EVENT_HOME):
 * LEFT_CALIBRATION 152, RIGHT_CALIBRATION 192, FRONT_LEFT_CALIBRATION 90,
 * FRONT_RIGHT_CALIBRATION 110 (l.60-65) */
static walls_ir_cal_t cal = { WALLS_IR_MAGIC, { 152, 192 }, { 90, 110 }, WALLS_IR_SIDE_PCT, WALLS_IR_FRONT_PCT, 0 };
static uint8_t sealed;

#define ROLES WALLS_IR_ROLES
#define ROLE_FRONT_L WALLS_IR_FRONT_L
#define ROLE_FRONT_R WALLS_IR_FRONT_R
#define ROLE_LEFT WALLS_IR_LEFT
#define ROLE_RIGHT WALLS_IR_RIGHT
#define sensor_of walls_ir_sensor

uint8_t walls_ir_sensor(uint8_t role)
{
    static const uint8_t advanced[ROLES] HAL_FLASH = { 0, 3, 1, 2 }, basic[ROLES] HAL_FLASH = { 0, 0, 2, 1 };
    uint8_t n = hal_ir_count();
    return n == 4 ? hal_flash_u8(&advanced[role]) : n == 3 ? hal_flash_u8(&basic[role]) : 255;
}

static uint8_t sum_before_check(const walls_ir_cal_t *c)
{
    const uint8_t *p = (const uint8_t *)c;
    uint8_t s = 0;
    for (uint8_t i = 0; i < (uint8_t)((const uint8_t *)&c->check - p); i++) s = (uint8_t)(s + p[i]);
    return s;
}

void walls_ir_cal_seal(walls_ir_cal_t *c)
{
    c->magic = WALLS_IR_MAGIC;
    c->check = (uint8_t)(0x5a - sum_before_check(c));
}

uint8_t walls_ir_cal_ok(const walls_ir_cal_t *c)
{
    return c->magic == WALLS_IR_MAGIC && (uint8_t)(c->check + sum_before_check(c)) == 0x5a && c->side_pct &&
           c->front_pct;
}

walls_ir_cal_t *walls_ir_cal(void)
{
    if (!sealed) {
        walls_ir_cal_seal(&cal);
        sealed = 1;
    }
    return &cal;
}

/* the mean of each role's reading over WALLS_IR_PASSES new passes */
static void average(uint16_t mean[ROLES])
{
    uint32_t sum[ROLES] = { 0, 0, 0, 0 };
    for (uint8_t k = 0; k < WALLS_IR_PASSES; k++) {
        uint8_t seq = hal_ir_seq();
        while (hal_ir_seq() == seq) {}
        for (uint8_t r = 0; r < ROLES; r++) sum[r] += hal_ir_raw(sensor_of(r));
    }
    for (uint8_t r = 0; r < ROLES; r++) mean[r] = (uint16_t)(sum[r] / WALLS_IR_PASSES);
}

/* a reference this small is no wall: 10 ADC counts (the detectors' dark
 * noise and the ambient light's flicker are a few counts) */
#define WALLS_IR_MIN_REF 10u

/* The pair of roles a and b averaged into ref[0], ref[1] of the
 * calibration, which is then sealed: 1, or 0 (nothing changed) without IR
 * or with a reference too small to be a wall. */
static uint8_t calibrate_pair(uint8_t a, uint8_t b, uint16_t ref[2])
{
    uint16_t m[ROLES];
    if (sensor_of(0) == 255) return 0;
    average(m);
    if (m[a] < WALLS_IR_MIN_REF || m[b] < WALLS_IR_MIN_REF) return 0;
    ref[0] = m[a];
    ref[1] = m[b];
    walls_ir_cal_seal(walls_ir_cal());
    return 1;
}

uint8_t walls_ir_calibrate_sides(void) { return calibrate_pair(ROLE_LEFT, ROLE_RIGHT, walls_ir_cal()->side_ref); }

uint8_t walls_ir_calibrate_front(void) { return calibrate_pair(ROLE_FRONT_L, ROLE_FRONT_R, walls_ir_cal()->front_ref); }

void walls_ir_levels(uint16_t pct[3])
{
    const walls_ir_cal_t *c = walls_ir_cal();
    uint8_t ok = sensor_of(0) != 255;
    uint32_t l = ok ? hal_ir_raw(sensor_of(ROLE_LEFT)) : 0, r = ok ? hal_ir_raw(sensor_of(ROLE_RIGHT)) : 0;
    uint32_t f = ok ? (uint32_t)hal_ir_raw(sensor_of(ROLE_FRONT_L)) + hal_ir_raw(sensor_of(ROLE_FRONT_R)) : 0;
    pct[0] = (uint16_t)(l * 100u / (c->side_ref[0] ? c->side_ref[0] : 1));
    pct[1] = (uint16_t)(f * 100u / ((uint32_t)c->front_ref[0] + c->front_ref[1] ? (uint32_t)c->front_ref[0] + c->front_ref[1] : 1));
    pct[2] = (uint16_t)(r * 100u / (c->side_ref[1] ? c->side_ref[1] : 1));
}
