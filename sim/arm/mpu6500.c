/* mpu6500.c - InvenSense MPU-6500 on SPI. Sources: MPU-6500 Product
 * Specification PS-MPU-6500A-01 rev 1.1, 03/05/2014 ("PS"): section 3.1,
 * Table 1, gyroscope specifications (sensitivity 131/65.5/32.8/16.4 LSB/(deg/s) at FS_SEL
 * 0..3, initial ZRO tolerance +-5 deg/s, rate noise spectral density 0.01
 * deg/s/sqrt(Hz), total RMS noise 0.1 deg/s at DLPFCFG 2 (92 Hz), which
 * 0.01 x sqrt(92) = 0.096 matches), 3.2 Table 2 accelerometer (16384 LSB/g
 * at +-2 g, halving per AFS_SEL), 3.3 Table 3 temperature sensor (333.87
 * LSB/degC, 0 LSB at 21 degC), 4.7 (0 g on X and Y, +1 g on Z when flat),
 * section 7.5 SPI interface (first byte: R/W bit 7 and
 * the address; data bytes follow, the address incrementing); Register Map
 * RM-MPU-6500A-00 rev 2.1 ("RM"): section 3 reset values (0x00 except
 * PWR_MGMT_1 0x01 and WHO_AM_I 0x70), registers 19-24 the gyro offsets
 * (OffsetLSB = OFFS_USR x 4 / 2^FS_SEL), 25 SMPLRT_DIV, 26 CONFIG (DLPF_CFG
 * bandwidths and rates), 27 GYRO_CONFIG (FS_SEL, FCHOICE_B), 28
 * ACCEL_CONFIG, 59-72 the sensor data, 104 SIGNAL_PATH_RESET, 106
 * USER_CTRL, 107 PWR_MGMT_1 (DEVICE_RESET, SLEEP), 108 PWR_MGMT_2, 117
 * WHO_AM_I. The RM says the offsets are subtracted; the parts add them
 * (InvenSense's and others' calibration code writes the negated bias, and
 * bulebule's mmlib/mpu.c does the same), so they are added here.
 *
 * The gyro Z output sample k, at t_k = k / f (f the output rate of CONFIG,
 * SMPLRT_DIV and FCHOICE_B), is held until sample k+1:
 *   y_k = w(t_k) + zro + sigma x n_k,  sigma = density x sqrt(bandwidth)
 * w the physics' rate (the callback), zro drawn once per part from N(0,
 * (5/3)^2) clamped to +-5 deg/s (the PS's tolerance read as a 3-sigma
 * bound), n_k one standard normal deviate per sample from the part's own
 * stream (world/rng.h, as sim/world/sensors/gyro.c draws its noise): every
 * sample draws, read or not, so the noise depends on time only. The output
 * is y_k x LSB/dps + the user offset, rounded, clamped to 16 bits. The data
 * registers are latched when a read transaction's address byte arrives, so
 * a burst read sees one sample. Stated limits: gyro X/Y read their offsets
 * only (a flat robot turns about Z); the accelerometer reads 0, 0, +1 g
 * without noise; the temperature reads 25 degC; no sensitivity error; the
 * SPI clock limits (1 MHz for writes, 20 MHz for sensor reads, PS 7.5) are
 * not checked; time is HCLK cycles over the current HCLK, summed access by
 * access. */
#include "arm/mpu6500.h"

#include <math.h>

enum { ZG_OFFS_H = 0x17, ZG_OFFS_L = 0x18, SMPLRT_DIV = 0x19, CONFIG = 0x1A, GYRO_CONFIG = 0x1B,
       ACCEL_CONFIG = 0x1C, ACCEL_XOUT_H = 0x3B, TEMP_OUT_H = 0x41, GYRO_XOUT_H = 0x43,
       SIGNAL_PATH_RESET = 0x68, USER_CTRL = 0x6A, PWR_MGMT_1 = 0x6B, PWR_MGMT_2 = 0x6C, WHO_AM_I = 0x75 };

#define READ_BIT        0x80u
#define PWR1_RESET      0x80u
#define PWR1_SLEEP      0x40u
#define PWR2_DISABLE_ZG 0x01u
#define USER_CTRL_AUTOCLEAR 0x07u /* SIG_COND_RST, I2C_MST_RST, FIFO_RST clear themselves */

#define ZRO_SIGMAS      3.0    /* ours: the tolerance as a 3-sigma bound */
#define DIE_TEMP_C      25.0   /* ours */
#define DEG_PER_RAD     (180.0 / M_PI)

static const double lsb_dps[4] = { 131.0, 65.5, 32.8, 16.4 }; /* PS Table 1 (the MPU-6050's PS 6.1 the same) */

struct mpu6500_part {
    uint8_t who_am_i, pwr1_default;
    double noise_dps_rthz, zro_bound_dps; /* rate noise spectral density; initial ZRO tolerance */
    double temp_lsb_c, temp_zero_c;       /* temperature sensitivity; the temperature reading 0 LSB */
    double dlpf_bw_hz[8];                 /* gyro bandwidth by CONFIG DLPF_CFG */
    bool fchoice;                         /* GYRO_CONFIG FCHOICE_B exists */
};

/* MPU-6500: RM 4.40 WHO_AM_I 0x70, RM section 3 PWR_MGMT_1 0x01, PS Table 1
 * noise and ZRO, PS Table 3 333.87 LSB/degC with 0 LSB at 21 degC, RM 4.3. */
const mpu6500_part_t mpu6500_part_6500 = { 0x70u, 0x01u, 0.01, 5.0, 333.87, 21.0,
                                           { 250, 184, 92, 41, 20, 10, 5, 3600 }, true };
/* MPU-6050: RM-MPU-6000A-00 rev 4.2 4.32 WHO_AM_I 0x68 and section 3
 * PWR_MGMT_1 0x40 (asleep), 4.3 DLPF_CFG bandwidths 256/188/98/42/20/10/5
 * Hz (7 reserved: taken as 256), 4.18 temperature = LSB / 340 + 36.53
 * degC; PS-MPU-6000A-00 rev 3.4 6.1 rate noise spectral density 0.005
 * deg/s/sqrt(Hz), initial ZRO tolerance +-20 deg/s; no FCHOICE. */
const mpu6500_part_t mpu6500_part_6050 = { 0x68u, 0x40u, 0.005, 20.0, 340.0, 36.53,
                                           { 256, 188, 98, 42, 20, 10, 5, 256 }, false };

/* The output rate (Hz) and noise bandwidth (Hz) of the current configuration (RM 4.3, 4.5). */
static void output_rate(const mpu6500_t *m, double *f_hz, double *bw_hz)
{
    unsigned fchoice_b = m->part->fchoice ? m->reg[GYRO_CONFIG] & 3u : 0u, dlpf = m->reg[CONFIG] & 7u;
    if (fchoice_b) { *f_hz = 32000.0; *bw_hz = (fchoice_b & 1u) ? 8800.0 : 3600.0; return; }
    *bw_hz = m->part->dlpf_bw_hz[dlpf];
    *f_hz = (dlpf == 0 || dlpf == 7) ? 8000.0 : 1000.0 / (1.0 + m->reg[SMPLRT_DIV]);
}

double mpu6500_sigma_dps(const mpu6500_t *m)
{
    double f, bw;
    output_rate(m, &f, &bw);
    return m->part->noise_dps_rthz * sqrt(bw);
}

double mpu6500_lsb_per_dps(const mpu6500_t *m) { return lsb_dps[(m->reg[GYRO_CONFIG] >> 3) & 3u]; }

static void set_time(mpu6500_t *m, uint64_t cycle)
{
    if (cycle > m->last_cycle && m->clk && m->clk->hclk)
        m->t_s += (double)(cycle - m->last_cycle) / m->clk->hclk;
    if (cycle > m->last_cycle) m->last_cycle = cycle;
}

/* Brings the held gyro Z sample to the current time. */
static void sample_gyro(mpu6500_t *m)
{
    double f, bw;
    output_rate(m, &f, &bw);
    int64_t k = (int64_t)floor(m->t_s * f);
    if (k <= m->sample) return;
    double n = 0.0;
    for (int64_t i = m->sample + 1; i <= k; i++) n = rng_gauss(&m->rng); /* every sample draws */
    m->sample = k;
    if ((m->reg[PWR_MGMT_1] & PWR1_SLEEP) || (m->reg[PWR_MGMT_2] & PWR2_DISABLE_ZG)) return;
    uint64_t dk = (uint64_t)llround(((double)k / f - m->t_s) * (m->clk ? m->clk->hclk : 0));
    uint64_t at = m->last_cycle >= dk ? m->last_cycle - dk : 0; /* the sample's own cycle (<= now) */
    double w = m->rate ? m->rate(m->rate_ctx, at) : 0.0;
    m->z_dps = w * DEG_PER_RAD + m->zro_dps + m->part->noise_dps_rthz * sqrt(bw) * n;
}

static void put16(mpu6500_t *m, unsigned reg, double v)
{
    long r = lround(v);
    if (r > 32767) r = 32767;
    if (r < -32768) r = -32768;
    uint16_t u = (uint16_t)(int16_t)r;
    m->reg[reg] = (uint8_t)(u >> 8);
    m->reg[reg + 1] = (uint8_t)u;
}

static double user_offset_lsb(const mpu6500_t *m, unsigned hi)
{
    int16_t offs = (int16_t)(uint16_t)(m->reg[hi] << 8 | m->reg[hi + 1]);
    return offs * 4.0 / (double)(1u << ((m->reg[GYRO_CONFIG] >> 3) & 3u));
}

/* The sensor data registers as a read transaction sees them. */
static void latch_data(mpu6500_t *m)
{
    sample_gyro(m);
    double lsb = mpu6500_lsb_per_dps(m);
    double g_lsb = 16384.0 / (double)(1u << ((m->reg[ACCEL_CONFIG] >> 3) & 3u));
    put16(m, ACCEL_XOUT_H, 0.0);
    put16(m, ACCEL_XOUT_H + 2, 0.0);
    put16(m, ACCEL_XOUT_H + 4, g_lsb);
    put16(m, TEMP_OUT_H, (DIE_TEMP_C - m->part->temp_zero_c) * m->part->temp_lsb_c);
    put16(m, GYRO_XOUT_H, user_offset_lsb(m, 0x13));
    put16(m, GYRO_XOUT_H + 2, user_offset_lsb(m, 0x15));
    put16(m, GYRO_XOUT_H + 4, floor(m->z_dps * lsb + 0.5) + user_offset_lsb(m, ZG_OFFS_H));
}

/* The registers the model implements: the gyro offsets, SMPLRT_DIV, CONFIG,
 * GYRO_CONFIG, ACCEL_CONFIG(2), the sensor data, SIGNAL_PATH_RESET,
 * USER_CTRL, PWR_MGMT_1/2, WHO_AM_I, the accelerometer offsets. */
static bool modeled(unsigned reg)
{
    return (reg >= 0x13 && reg <= 0x1D) || (reg >= 0x3B && reg <= 0x48) || reg == SIGNAL_PATH_RESET
        || (reg >= USER_CTRL && reg <= PWR_MGMT_2) || reg == WHO_AM_I || (reg >= 0x77 && reg <= 0x7E);
}

static void note_access(mpu6500_t *m, unsigned reg)
{
    if (modeled(reg)) return;
    m->unmodeled_count++;
    m->unmodeled_map[reg / 8] |= (uint8_t)(1u << (reg % 8));
}

bool mpu6500_unmodeled(const mpu6500_t *m, unsigned reg)
{
    return reg < 128 && (m->unmodeled_map[reg / 8] >> (reg % 8)) & 1u;
}

static bool read_only(unsigned reg) { return reg == WHO_AM_I || (reg >= 0x3A && reg <= 0x60); }

static void write_reg(mpu6500_t *m, unsigned reg, uint8_t v)
{
    if (read_only(reg)) return;
    bool rate_cfg = reg == SMPLRT_DIV || reg == CONFIG || reg == GYRO_CONFIG;
    if (reg == PWR_MGMT_1 && (v & PWR1_RESET)) { mpu6500_reset(m); return; }
    if (reg == SIGNAL_PATH_RESET) v = 0;          /* its bits clear themselves */
    if (reg == USER_CTRL) v &= (uint8_t)~USER_CTRL_AUTOCLEAR;
    sample_gyro(m);
    m->reg[reg] = v;
    if (rate_cfg) { /* the sample count restarts at the new rate; the held sample stays */
        double f, bw;
        output_rate(m, &f, &bw);
        m->sample = (int64_t)floor(m->t_s * f) - 1;
    }
}

uint8_t mpu6500_exchange(void *dev, uint8_t mosi, uint64_t cycle)
{
    mpu6500_t *m = dev;
    if (!m->selected) return 0xFFu;
    set_time(m, cycle);
    if (!m->have_addr) {
        m->have_addr = true;
        m->reading = (mosi & READ_BIT) != 0;
        m->addr = mosi & 0x7Fu;
        if (m->reading) latch_data(m);
        return 0x00u;
    }
    uint8_t out = 0x00u;
    note_access(m, m->addr);
    if (m->reading) out = m->reg[m->addr];
    else write_reg(m, m->addr, mosi);
    m->addr = (m->addr + 1) & 0x7Fu; /* burst: the address increments (PS 7.5) */
    return out;
}

void mpu6500_select(mpu6500_t *m, bool ncs_level)
{
    m->selected = !ncs_level;
    m->have_addr = false; /* each edge starts or ends a transaction */
}

void mpu6500_reset(mpu6500_t *m)
{
    for (unsigned i = 0; i < sizeof m->reg; i++) m->reg[i] = 0;
    m->reg[PWR_MGMT_1] = m->part->pwr1_default;
    m->reg[WHO_AM_I] = m->part->who_am_i;
    double f, bw;
    output_rate(m, &f, &bw);
    m->sample = (int64_t)floor(m->t_s * f) - 1; /* the current sample is computed when read */
    m->z_dps = 0.0;
}

static void init_part(mpu6500_t *m, const mpu6500_part_t *part, const mmio_clocks_t *clk, mpu6500_rate_fn rate,
                      void *rate_ctx, uint64_t seed, unsigned index)
{
    *m = (mpu6500_t){ 0 };
    m->part = part;
    m->clk = clk;
    m->rate = rate;
    m->rate_ctx = rate_ctx;
    rng_init(&m->rng, seed, MPU6500_RNG_STREAM + index);
    double bound = part->zro_bound_dps, z = bound / ZRO_SIGMAS * rng_gauss(&m->rng);
    m->zro_dps = z > bound ? bound : z < -bound ? -bound : z;
    m->selected = false;
    m->sample = -1;
    mpu6500_reset(m);
}

void mpu6500_init(mpu6500_t *m, const mmio_clocks_t *clk, mpu6500_rate_fn rate, void *rate_ctx,
                  uint64_t seed, unsigned index)
{
    init_part(m, &mpu6500_part_6500, clk, rate, rate_ctx, seed, index);
}

void mpu6050_init(mpu6500_t *m, const mmio_clocks_t *clk, mpu6500_rate_fn rate, void *rate_ctx,
                  uint64_t seed, unsigned index)
{
    init_part(m, &mpu6500_part_6050, clk, rate, rate_ctx, seed, index);
}

/* I2C (PS 9.3 / MPU-6050 PS 9.3): a write transfer's first byte sets the
 * register address, later bytes write registers; a read transfer reads from
 * the address, incrementing; the data registers are latched at the read
 * transfer's START so a burst sees one sample. */
bool mpu6500_i2c_start(void *dev, bool read, uint64_t cycle)
{
    mpu6500_t *m = dev;
    set_time(m, cycle);
    m->reading = read;
    m->have_addr = read; /* a read continues from the address set before */
    if (read) latch_data(m);
    return true;
}

bool mpu6500_i2c_write(void *dev, uint8_t byte, uint64_t cycle)
{
    mpu6500_t *m = dev;
    set_time(m, cycle);
    if (!m->have_addr) { m->have_addr = true; m->addr = byte & 0x7Fu; return true; }
    note_access(m, m->addr);
    write_reg(m, m->addr, byte);
    m->addr = (m->addr + 1) & 0x7Fu;
    return true;
}

uint8_t mpu6500_i2c_read(void *dev, uint64_t cycle)
{
    mpu6500_t *m = dev;
    set_time(m, cycle);
    note_access(m, m->addr);
    uint8_t out = m->reg[m->addr];
    m->addr = (m->addr + 1) & 0x7Fu;
    return out;
}

void mpu6500_i2c_stop(void *dev, uint64_t cycle)
{
    mpu6500_t *m = dev;
    set_time(m, cycle);
    m->have_addr = false;
}
