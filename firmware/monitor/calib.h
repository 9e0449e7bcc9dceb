/* SPDX-License-Identifier: MIT */
/*
 * calib: the monitor's calibration block: every parameter of the model
 * (shared/model.md section 8) plus CAN identifiers, periods and thresholds.
 *
 * The block is the same bytes for both numeric builds: model parameters are
 * stored in the fixed build's Q-formats (squeal_model.h), everything else as
 * integers with the unit in the field name. Stored form (little-endian):
 *
 *   offset  size  field
 *   0       4     magic "SQCB"
 *   4       2     layout version (CALIB_VERSION)
 *   6       2     total length in bytes (CALIB_BLOCK_LEN)
 *   8       ...   the fields of calib_t in declaration order (u8/u16/u32/i32)
 *   len-4   4     CRC-32 (IEEE 802.3, reflected 0xEDB88320, init/xorout
 *                 0xFFFFFFFF; check value over "123456789" 0xCBF43926)
 *                 over bytes 0 .. len-5
 *
 * A block is accepted only whole: magic, version, length, CRC and the range
 * of every field must all be right, otherwise calib_decode() leaves the
 * output untouched and says why (never half-applied).
 */
#ifndef CALIB_H
#define CALIB_H

#include <stdbool.h>
#include <stdint.h>

#include "squeal_model.h"

#define CALIB_MAGIC 0x42435153UL /* "SQCB" little-endian */
#define CALIB_VERSION 2U /* 2: input_bus, output_bus, input_listen_only */

typedef struct {
	/* model (fixed-build Q-formats, see squeal_model.h) */
	int32_t mass_q16;        /* m [kg]                           1.0   */
	int32_t omega0_q12;      /* w0 [rad/s]                       5000  */
	int32_t damping_q30;     /* D [-]                            0.023 */
	int32_t mu_inf_q30;      /* mu_inf [-]                       0.25  */
	int32_t delta_mu_q30;    /* mu_0 - mu_inf [-]                0.15  */
	int32_t slope_q24;       /* a [s/m]                          2.0   */
	uint8_t criterion;       /* squeal_criterion_t               exact */
	/* geometry */
	uint32_t pad_radius_um;   /* r_p, effective pad radius       120000 */
	uint32_t wheel_radius_um; /* r_w, rolling radius             300000 */
	/* CAN interface (11-bit identifiers) */
	uint16_t bitrate_kbps;       /*                                 500 */
	uint16_t disc_speed_id;      /*                               0x110 */
	uint16_t pad_force_id;       /*                               0x111 */
	uint16_t status_id;          /*                               0x300 */
	uint16_t detail_id;          /*                               0x301 */
	uint16_t diag_id;            /*                               0x302 */
	uint16_t detail2_id;         /*                               0x303 */
	uint8_t e2e_check_inputs;    /* 1 check DiscSpeed/PadForce E2E    1 */
	uint8_t e2e_max_delta_counter; /* P01 MaxDeltaCounterInit          2 */
	/* periods */
	uint16_t input_period_ms;    /* expected input period            10 */
	uint16_t status_period_ms;   /* SquealStatus                     10 */
	uint16_t detail_period_ms;   /* SquealDetail + SquealDetail2    100 */
	uint16_t diag_period_ms;     /* SquealDiag                     1000 */
	uint8_t stale_cycles;        /* missed input periods -> stale     3 */
	/* plausibility of the inputs (raw signal units of the DBC) */
	uint16_t speed_max_raw;        /* DiscSpeed_radps x0.01 max   40000 */
	uint16_t speed_step_max_raw;   /* max change between frames    1000 */
	uint16_t force_max_raw;        /* PadForce_N x0.5 max         60000 */
	uint16_t force_step_max_raw;   /* max change between frames   20000 */
	uint16_t lowpass_alpha_q15;    /* first-order filter, 32768 = off   */
	/* classification */
	uint32_t v0_min_umps;        /* not sliding below [um/s]     10000 */
	uint32_t force_min_mn;       /* not sliding below [mN]      100000 */
	uint8_t debounce_count;      /* agreeing classifications        3 */
	uint32_t hyst_lnq_micro;     /* Hopf band, |ln 2Q| [1e-6]   20000 */
	uint32_t hyst_rho_ppm;       /* stable band, |rho - 1| [ppm] 20000 */
	uint32_t rho_warn_ppm;       /* bistable: rho below -> level 2 500000 */
	/* platform */
	uint16_t watchdog_ms;        /* IWDG / software watchdog       100 */
	/* buses (hal.h: 0 .. HAL_CAN_BUSES-1; version 2) */
	uint8_t input_bus;           /* DiscSpeed/PadForce come from      0 */
	uint8_t output_bus;          /* Squeal* frames go out on          0 */
	uint8_t input_listen_only;   /* 1: never send on the input bus    0 */
} calib_t;

/* Size of the stored block: header 8 + fields + CRC 4. */
#define CALIB_BLOCK_LEN 106U

/* Why a block was refused (calib_decode's *reason). */
typedef enum {
	CALIB_OK = 0,
	CALIB_ERR_LENGTH,  /* buffer shorter than the block / length field */
	CALIB_ERR_MAGIC,
	CALIB_ERR_VERSION,
	CALIB_ERR_CRC,
	CALIB_ERR_RANGE,   /* a field outside its documented range         */
	CALIB_ERR_BITRATE  /* bit rate in range but not one every ECU clock
			    * times exactly (10, 20, 50, 100, 125, 250, 500,
			    * 1000 kbit/s; 800 is not exact at 42 MHz)     */
} calib_error_t;

/* The factory defaults (model.md section 8, the DBC's IDs and periods). */
void calib_default(calib_t *cal);

/* Range check of every field. SQ_OK or SQ_EINVAL. NULL pointers given to
 * any calib_* function are programming errors: hal_contract_failed(). */
int calib_validate(const calib_t *cal);

/* Serialize (always CALIB_BLOCK_LEN bytes; a shorter buffer is a
 * programming error). SQ_OK, SQ_EINVAL (a calibration that does not
 * validate). */
int calib_encode(const calib_t *cal, uint8_t *buf, uint32_t buf_len);

/* Parse and check a stored block. SQ_OK (*cal written), SQ_EBADMSG (with
 * *reason; *cal untouched). reason may be NULL. */
int calib_decode(const uint8_t *buf, uint32_t len, calib_t *cal,
		 calib_error_t *reason);

/*
 * The valid stored range of the field at byte offset `offset` in calib_t
 * (offsetof), from the same table calib_validate() uses, so that other
 * front ends (the text file parser) need no copy of it.
 * SQ_OK, SQ_ENOENT (no field starts there).
 */
int calib_field_range(uint32_t offset, int64_t *min, int64_t *max);

/* The model's parameters from a valid calibration. */
void calib_model_params(const calib_t *cal, squeal_params_t *params);

/* CRC-32 (IEEE 802.3), continuing from crc (start with 0). */
uint32_t calib_crc32(uint32_t crc, const uint8_t *data, uint32_t len);

const char *calib_error_name(calib_error_t err);

#endif /* CALIB_H */
