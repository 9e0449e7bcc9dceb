/* SPDX-License-Identifier: MIT */
/*
 * calib: the monitor's calibration block: every parameter of the model
 * (docs/model.md section 8) plus CAN identifiers, periods and thresholds.
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

#include "can_signal.h"
#include "input_conv.h"
#include "squeal_model.h"
#include "squeal_sigma.h"

#define CALIB_MAGIC 0x42435153UL /* "SQCB" little-endian */
#define CALIB_VERSION 4U /* 2: buses, input map and corners; 3: 64-bit decimals,
                          * selector ranges and a second selector, torque share;
                          * 4: CAN FD inputs (fd, min_dlc to 64, start and
                          * qualifier bits to 511), E2E P05 and its offset */

/*
 * The input map (docs/calib-input-map.md). n_corners == 0 is the legacy
 * form: one corner FL on DiscSpeed/PadForce from the flat keys (P01 or none,
 * input_period_ms, *_max_raw); that is calib_default(). Otherwise inputs
 * [0, n_inputs) and corners [0, n_corners) are used and the legacy input
 * keys are ignored. Unused entries are stored as zeros.
 */
#define CALIB_MAX_INPUTS 8U
#define CALIB_MAX_CORNERS 4U
#define CALIB_DATA_ID_LIST_LEN 16U

/* input flags */
#define CALIB_IN_EXTENDED (1U << 0)  /* 29-bit identifier                   */
#define CALIB_IN_MUX      (1U << 1)  /* multiplexed: mux selector in range  */
#define CALIB_IN_NA       (1U << 2)  /* na_raw means "not available"        */
#define CALIB_IN_NA2      (1U << 3)  /* na_raw2 too                         */
#define CALIB_IN_QUALIFIER (1U << 4) /* qualifier_bit marks invalid         */
#define CALIB_IN_DLC_EXACT (1U << 5) /* DLC must equal min_dlc              */
#define CALIB_IN_MUX2     (1U << 6)  /* a second selector too (needs MUX)   */
#define CALIB_IN_FLAGS_ALL 0x7FU

/* calib_input_t.protection */
#define CALIB_PROT_NONE    0U
#define CALIB_PROT_P01     1U /* AUTOSAR E2E P01 1A: CRC byte 0, counter byte 1 */
#define CALIB_PROT_P02     2U /* AUTOSAR E2E P02: CRC-8H2F, DataIDList          */
#define CALIB_PROT_COUNTER 3U /* alive counter signal only                      */
#define CALIB_PROT_P05     4U /* AUTOSAR E2E P05: CRC-16 + 8-bit counter at
                               * e2e_offset_byte, data_id                      */
#define CALIB_PROT_COUNT   5U

/* A decimal as DBC files write it: mant x 10^exp, up to 17 significant
 * digits (|mant| <= INPUT_DEC_MANT_MAX), exp INPUT_DEC_EXP_MIN..MAX
 * (input_conv.h, which converts it exactly). */
typedef input_dec_t calib_dec_t;

/*
 * Standard deviations of the brake's parameters (docs/uncertainty.md),
 * in the Q formats of the parameters they belong to; all zero (the default)
 * is today's crisp classification. Domain: 0 <= sd <= |parameter|,
 * |corr| <= 1 (calib_validate).
 */
typedef struct {
	int32_t mass_sd_q16;       /* sd of m                                 */
	int32_t omega0_sd_q12;     /* sd of w0                                */
	int32_t damping_sd_q30;    /* sd of D                                 */
	int32_t mu_inf_sd_q30;     /* sd of mu_inf (enters no border)         */
	int32_t delta_mu_sd_q30;   /* sd of delta_mu                          */
	int32_t slope_sd_q24;      /* sd of a                                 */
	int32_t slope_delta_mu_corr_q30; /* corr(a, delta_mu), -1 .. 1       */
} calib_sd_t;

/* Members ordered by alignment so that calib_t (on the ECU's stack while a
 * block is decoded) carries little padding; the stored order is calib.c's
 * table, not this one. */
typedef struct {
	calib_dec_t factor;        /* physical = raw x factor + offset        */
	calib_dec_t offset;
	calib_dec_t max;           /* plausible range and step, physical      */
	calib_dec_t min;
	calib_dec_t step_max;
	uint32_t id;               /* 11- or 29-bit identifier                */
	uint32_t mux_value;        /* selector range (CALIB_IN_MUX):          */
	uint32_t mux_value_max;    /*   mux_value .. mux_value_max, inclusive */
	uint32_t mux2_value;       /* second selector's range (CALIB_IN_MUX2) */
	uint32_t mux2_value_max;
	uint32_t na_raw;           /* CALIB_IN_NA                             */
	uint32_t na_raw2;          /* CALIB_IN_NA2                            */
	uint16_t data_id;          /* P01, P05                                */
	uint16_t period_ms;        /* expected period                         */
	uint16_t qualifier_bit;    /* DBC bit number (CALIB_IN_QUALIFIER)     */
	can_signal_t sig;          /* the value                               */
	can_signal_t mux;          /* selector (CALIB_IN_MUX): the outer one  */
	can_signal_t mux2;         /* inner selector (CALIB_IN_MUX2)          */
	can_signal_t counter;      /* CALIB_PROT_COUNTER                      */
	uint8_t flags;             /* CALIB_IN_*                              */
	uint8_t min_dlc;           /* shorter frames: bad DLC (data length in
				    * bytes, 0..8, with fd up to 64)         */
	uint8_t fd;                /* 1: a CAN FD message (a classic frame
				    * with its id is of the wrong format)     */
	uint8_t unit;              /* input_unit_t                            */
	uint8_t qualifier_invalid; /* the bit's value that means invalid     */
	uint8_t protection;        /* CALIB_PROT_*                            */
	uint8_t data_id_list[CALIB_DATA_ID_LIST_LEN]; /* P02                  */
	uint8_t counter_modulus;   /* 2..16                                   */
	uint8_t max_delta_counter; /* largest accepted counter step (P05:
				    * 1..255)                                 */
	uint8_t e2e_offset_byte;   /* P05: CRC bytes off, off+1, counter off+2 */
	uint8_t stale_cycles;      /* missed periods before stale             */
	/* Not stored: the share of the value the conversion applies, 1e-6 (0:
	 * the whole value). 0 in calib_t.inputs[]; calib_corner_view() sets it
	 * on the copy of a corner's torque input from the corner's
	 * torque_share_ppm, so that every user of that copy converts alike. */
	uint32_t conv_share_ppm;
} calib_input_t;

typedef struct {
	uint8_t pos;               /* 0 FL, 1 FR, 2 RL, 3 RR                  */
	uint8_t speed_input;       /* index into inputs                       */
	uint8_t force_input;
	uint8_t friction_faces;    /* torque: n_f                             */
	uint32_t piston_area_cmm2; /* pressure: A [0.01 mm^2]                 */
	uint32_t efficiency_ppm;   /* pressure: eta                           */
	uint32_t axle_factor_ppm;  /* pressure: k                             */
	uint32_t torque_share_ppm; /* torque: share of the input acting here  */
	int32_t mass_q16;          /* the corner's brake, as the flat keys    */
	int32_t omega0_q12;
	int32_t damping_q30;
	int32_t mu_inf_q30;
	int32_t delta_mu_q30;
	int32_t slope_q24;
	uint8_t criterion;
	uint32_t pad_radius_um;
	uint32_t wheel_radius_um;
	uint16_t status_id;
	uint16_t detail_id;
	uint16_t detail2_id;
	uint16_t diag_id;
	calib_sd_t sd;             /* the corner's brake's deviations         */
} calib_corner_t;

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
	/* buses (hal.h: 0 .. HAL_CAN_BUSES-1) */
	uint8_t input_bus;           /* the inputs come from              0 */
	uint8_t output_bus;          /* Squeal* frames go out on          0 */
	uint8_t input_listen_only;   /* 1: never send on the input bus    0 */
	/* input map and corners (0 corners: the legacy flat keys above) */
	uint8_t n_inputs;
	uint8_t n_corners;
	/* uncertainty: the flat brake's deviations (every corner
	 * inherits them) and k of the "uncertain" rule */
	calib_sd_t sd;               /* all 0: crisp classes               0 */
	int32_t uncertain_k_q16;     /* k [sigma], SQUEAL_Q_MARGIN         2 */
	calib_input_t inputs[CALIB_MAX_INPUTS];
	calib_corner_t corners[CALIB_MAX_CORNERS];
} calib_t;

/* Size of the stored block: header 8 + fields + CRC 4 (v1: 103 bytes, then
 * 3 bus bytes, 2 counts, the flat deviations and k, 8 inputs of
 * CALIB_INPUT_STORED_LEN (five decimals of 9 bytes, three selector range
 * ends and the second selector; v4: four start bits and the qualifier bit
 * in 2 bytes, fd, e2e_offset_byte), 4 corners of CALIB_CORNER_STORED_LEN
 * (with torque share and deviations): 1496 bytes, within the two 1 KiB
 * flash pages of a slot). */
#define CALIB_SD_STORED_LEN 28U
#define CALIB_INPUT_STORED_LEN 125U
#define CALIB_CORNER_STORED_LEN (61U + CALIB_SD_STORED_LEN)
#define CALIB_BLOCK_LEN (103U + 3U + 2U + CALIB_SD_STORED_LEN + 4U + \
			 (CALIB_MAX_INPUTS * CALIB_INPUT_STORED_LEN) + \
			 (CALIB_MAX_CORNERS * CALIB_CORNER_STORED_LEN))

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

/* The factory defaults (docs/model.md section 8, the DBC's IDs and periods). */
void calib_default(calib_t *cal);
/* The same, as one read-only object. */
const calib_t *calib_factory(void);

/* Range check of every field. SQ_OK or SQ_EINVAL. NULL pointers given to
 * any calib_* function are programming errors: hal_contract_failed(). */
int calib_validate(const calib_t *cal);
/* The same, saying why (CALIB_ERR_RANGE or CALIB_ERR_BITRATE). */
calib_error_t calib_check(const calib_t *cal);
/* The part of calib_validate() about the deviations (flat and every corner
 * slot in squeal_sigma_sd_check()'s domain): SQ_OK or SQ_EINVAL. */
int calib_sd_validate(const calib_t *cal);

/* Serialize (always CALIB_BLOCK_LEN bytes; a shorter buffer is a
 * programming error). SQ_OK, SQ_EINVAL (a calibration that does not
 * validate). */
int calib_encode(const calib_t *cal, uint8_t *buf, uint32_t buf_len);

/* Parse and check a stored block. SQ_OK (*cal written), SQ_EBADMSG (with
 * *reason; *cal untouched). reason may be NULL. buf may be the bytes of
 * the output object itself: the block is read whole before it is written
 * (squeal_app reads the stored block into the calib_t it decodes into). */
int calib_decode(const uint8_t *buf, uint32_t len, calib_t *cal,
		 calib_error_t *reason);

/*
 * The valid stored range of the field at byte offset `offset` in calib_t
 * (offsetof), from the same table calib_validate() uses, so that other
 * front ends (the text file parser) need no copy of it.
 * SQ_OK, SQ_ENOENT (no field starts there).
 */
int calib_field_range(uint32_t offset, int64_t *min, int64_t *max);

/* The model's parameters from a valid calibration (its flat keys), or
 * from one corner. */
void calib_model_params(const calib_t *cal, squeal_params_t *params);
void calib_corner_params(const calib_corner_t *corner, squeal_params_t *params);
/* The standard deviations of one corner's brake (squeal_sigma.h's form). */
void calib_corner_sd(const calib_corner_t *corner, squeal_param_sd_t *sd);
/* k of the "uncertain" rule in SQUEAL_Q_MARGIN's format (float: sigmas). */
squeal_num_t calib_uncertain_k(const calib_t *cal);

/* CRC-32 (IEEE 802.3), continuing from crc (start with 0). */
uint32_t calib_crc32(uint32_t crc, const uint8_t *data, uint32_t len);

const char *calib_error_name(calib_error_t err);

#endif /* CALIB_H */
