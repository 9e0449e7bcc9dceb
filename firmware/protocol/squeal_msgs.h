/* SPDX-License-Identifier: MIT */
/*
 * squeal_msgs: encode/decode of the monitor's CAN messages, as described by
 * squeal.dbc (the single description of the interface; a test proves that
 * every define and descriptor here equals the DBC).
 *
 * Naming: DBC message DiscSpeed -> MSG_DISC_SPEED_* defines, msg_disc_speed_t,
 * msg_disc_speed_pack()/unpack(); DBC signal DiscSpeed_radps -> field
 * disc_speed_radps. All struct fields are RAW signal values (integers as on
 * the bus): physical = (raw * factor_num + offset_num) / factor_den, see
 * msg_sig_table. No floating point here: the monitor converts.
 *
 * Conventions of every message (see the DBC's comments):
 *   - Intel (little-endian) signals, classic CAN, 11-bit identifiers;
 *   - byte 0 E2E CRC, byte 1 bits 0..3 E2E alive counter (e2e_p01.h);
 *     pack() writes the struct's crc/counter fields as they are, then
 *     e2e_p01_protect() overwrites them with the real ones;
 *   - reserved bits are sent as 0 and ignored on receive;
 *   - "not available" (MSG_*_NA): unsigned signal all ones, signed signal
 *     the most negative raw value; a value beyond the range is sent as the
 *     range's end (the sender saturates, see the *_MAX defines);
 *   - pack() refuses a raw value outside [min, max] that is not the NA value
 *     (SQ_ERANGE), so a bug in a conversion never reaches the bus silently.
 *
 * DLC: unpack() accepts exactly the message's DLC, anything else is
 * SQ_EBADMSG (so are a counter of 15 and a SquealDiag page > 3).
 */
#ifndef SQUEAL_MSGS_H
#define SQUEAL_MSGS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "e2e_p01.h"
#include "squeal_state.h"

#define MSG_MAX_DLC 8U

/* ---- DiscSpeed: wheel-speed ECU -> monitor ------------------------------ */
#define MSG_DISC_SPEED_ID          0x110U
#define MSG_DISC_SPEED_DLC         4U
#define MSG_DISC_SPEED_PERIOD_MS   10U
#define MSG_DISC_SPEED_DATA_ID     0x2C51U
#define MSG_DISC_SPEED_RADPS_MAX   65534U /* x 0.01 rad/s = 655.34 rad/s */
#define MSG_DISC_SPEED_RADPS_NA    0xFFFFU

typedef struct {
	uint8_t crc;
	uint8_t counter;
	uint16_t disc_speed_radps; /* DiscSpeed_radps, 0.01 rad/s */
} msg_disc_speed_t;

/* ---- PadForce: pad force sensor -> monitor ------------------------------ */
#define MSG_PAD_FORCE_ID           0x111U
#define MSG_PAD_FORCE_DLC          4U
#define MSG_PAD_FORCE_PERIOD_MS    10U
#define MSG_PAD_FORCE_DATA_ID      0x2C52U
#define MSG_PAD_FORCE_N_MAX        65534U /* x 0.5 N = 32767 N */
#define MSG_PAD_FORCE_N_NA         0xFFFFU

typedef struct {
	uint8_t crc;
	uint8_t counter;
	uint16_t pad_force_n; /* PadForce_N, 0.5 N */
} msg_pad_force_t;

/* ---- SquealStatus: monitor -> vehicle, 10 ms and on change -------------- */
#define MSG_SQUEAL_STATUS_ID        0x300U
#define MSG_SQUEAL_STATUS_DLC       8U
#define MSG_SQUEAL_STATUS_PERIOD_MS 10U
#define MSG_SQUEAL_STATUS_DATA_ID   0x3A01U
/* SquealState values (VAL_ table): the model's squeal_state_t, whose
 * INVALID is the bus's FAULT (squeal_state.h defines them once) */
#define MSG_SQUEAL_STATE_STABLE      ((uint8_t)SQUEAL_STATE_STABLE)
#define MSG_SQUEAL_STATE_BISTABLE    ((uint8_t)SQUEAL_STATE_BISTABLE)
#define MSG_SQUEAL_STATE_UNSTABLE    ((uint8_t)SQUEAL_STATE_UNSTABLE)
#define MSG_SQUEAL_STATE_NOT_SLIDING ((uint8_t)SQUEAL_STATE_NOT_SLIDING)
#define MSG_SQUEAL_STATE_FAULT       ((uint8_t)SQUEAL_STATE_INVALID)
/* WarningLevel values */
#define MSG_WARNING_LEVEL_NONE       0U
#define MSG_WARNING_LEVEL_ADVISORY   1U
#define MSG_WARNING_LEVEL_WARNING    2U
#define MSG_WARNING_LEVEL_CRITICAL   3U
#define MSG_BASIN_RATIO_MAX          10000U /* x 0.0001 = 1.0 */
#define MSG_BASIN_RATIO_NA           0xFFFFU
#define MSG_HOPF_MARGIN_MPS_MIN      (-32767) /* x 0.01 m/s */
#define MSG_HOPF_MARGIN_MPS_MAX      32767
#define MSG_HOPF_MARGIN_MPS_NA       (-32768)
/* BorderMargin_sigma: physical = raw x 0.1 - 0.1 sigma. 0 = not available
 * (no class, no deviations calibrated, no border), 1..254 = 0.0..25.3,
 * 255 = 25.4 or more (saturated). */
#define MSG_BORDER_MARGIN_SIGMA_NA   0U
#define MSG_BORDER_MARGIN_SIGMA_SAT  255U

typedef struct {
	uint8_t crc;
	uint8_t counter;
	uint8_t squeal_state;   /* SquealState, MSG_SQUEAL_STATE_* (0..3, 15) */
	uint8_t warning_level;  /* WarningLevel, 0..3                         */
	uint16_t basin_ratio;   /* BasinRatio, 0.0001                         */
	int16_t hopf_margin_mps; /* HopfMargin_mps, 0.01 m/s                  */
	uint8_t border_margin_sigma; /* BorderMargin_sigma, see above         */
} msg_squeal_status_t;

/* ---- SquealDetail: monitor -> vehicle, 100 ms (speeds) ------------------ */
#define MSG_SQUEAL_DETAIL_ID          0x301U
#define MSG_SQUEAL_DETAIL_DLC         8U
#define MSG_SQUEAL_DETAIL_PERIOD_MS   100U
#define MSG_SQUEAL_DETAIL_DATA_ID     0x3A02U
#define MSG_V0_MPS_MAX                16382U /* x 0.01 m/s = 163.82 m/s */
#define MSG_V0_MPS_NA                 0x3FFFU
#define MSG_HOPF_SPEED_MPS_MAX        16382U /* x 0.01 m/s */
#define MSG_HOPF_SPEED_MPS_NA         0x3FFFU
#define MSG_TRIGGER_VELOCITY_MPS_MAX  4094U  /* x 0.01 m/s = 40.94 m/s */
#define MSG_TRIGGER_VELOCITY_MPS_NA   0xFFFU
#define MSG_VEHICLE_SPEED_BORDER_KPH_MAX 4094U /* x 0.1 km/h = 409.4 km/h */
#define MSG_VEHICLE_SPEED_BORDER_KPH_NA  0xFFFU

typedef struct {
	uint8_t crc;
	uint8_t counter;
	uint16_t v0_mps;                 /* V0_mps, 0.01 m/s                 */
	uint16_t hopf_speed_mps;         /* HopfSpeed_mps, 0.01 m/s          */
	uint16_t trigger_velocity_mps;   /* TriggerVelocity_mps, 0.01 m/s    */
	uint16_t vehicle_speed_border_kph; /* VehicleSpeedBorder_kph, 0.1 km/h */
} msg_squeal_detail_t;

/* ---- SquealDetail2: monitor -> vehicle, 100 ms (forces, amplitude) ------ */
#define MSG_SQUEAL_DETAIL2_ID         0x303U
#define MSG_SQUEAL_DETAIL2_DLC        8U
#define MSG_SQUEAL_DETAIL2_PERIOD_MS  100U
#define MSG_SQUEAL_DETAIL2_DATA_ID    0x3A04U
#define MSG_FORCE_N_MAX               65534U /* x 0.5 N = 32767 N */
#define MSG_FORCE_N_NA                0xFFFFU
#define MSG_HOPF_FORCE_N_MAX          65534U /* x 1 N */
#define MSG_HOPF_FORCE_N_NA           0xFFFFU
#define MSG_LC_AMPLITUDE_UM_MAX       65534U /* x 0.1 um = 6553.4 um */
#define MSG_LC_AMPLITUDE_UM_NA        0xFFFFU

typedef struct {
	uint8_t crc;
	uint8_t counter;
	uint16_t force_n;          /* Force_N, 0.5 N          */
	uint16_t hopf_force_n;     /* HopfForce_N, 1 N        */
	uint16_t lc_amplitude_um;  /* LcAmplitude_um, 0.1 um  */
} msg_squeal_detail2_t;

/* ---- SquealDiag: monitor -> vehicle, 1000 ms, multiplexed --------------- */
#define MSG_SQUEAL_DIAG_ID          0x302U
#define MSG_SQUEAL_DIAG_DLC         8U
#define MSG_SQUEAL_DIAG_PERIOD_MS   1000U
#define MSG_SQUEAL_DIAG_DATA_ID     0x3A03U
/* SquealDiag_Page: which counters bytes 4..7 carry (send 0,1,2,3,0,...) */
#define MSG_DIAG_PAGE_UPTIME        0U /* Uptime_s, BusOffCount             */
#define MSG_DIAG_PAGE_TASK          1U /* WorstTaskTime_us, RxOverrunCount  */
#define MSG_DIAG_PAGE_E2E           2U /* E2eErrorCountSpeed/Force          */
#define MSG_DIAG_PAGE_FRAMES        3U /* TxOverflowCount, RxBadFrameCount  */
#define MSG_DIAG_PAGE_SELFTEST      4U /* the bring-up self-test           */
#define MSG_DIAG_PAGE_COUNT         5U
/* fault_bits: bit i is the 1-bit signal at start bit 16 + i */
#define MSG_FAULT_SPEED_STALE        (1U << 0)  /* Fault_SpeedStale       */
#define MSG_FAULT_FORCE_STALE        (1U << 1)  /* Fault_ForceStale       */
#define MSG_FAULT_E2E_SPEED          (1U << 2)  /* Fault_E2eSpeed         */
#define MSG_FAULT_E2E_FORCE          (1U << 3)  /* Fault_E2eForce         */
#define MSG_FAULT_SPEED_IMPLAUSIBLE  (1U << 4)  /* Fault_SpeedImplausible */
#define MSG_FAULT_FORCE_IMPLAUSIBLE  (1U << 5)  /* Fault_ForceImplausible */
#define MSG_FAULT_CALIB_INVALID      (1U << 6)  /* Fault_CalibInvalid     */
#define MSG_FAULT_BUS_OFF_SEEN       (1U << 7)  /* Fault_BusOffSeen       */
#define MSG_FAULT_CLOCK_FALLBACK     (1U << 8)  /* Fault_ClockFallback    */
#define MSG_FAULT_CAN_INIT           (1U << 9)  /* Fault_CanInit          */
#define MSG_FAULT_TX_OVERFLOW        (1U << 10) /* Fault_TxOverflow       */
#define MSG_FAULT_SELF_TEST          (1U << 11) /* Fault_SelfTest         */
#define MSG_FAULT_ALL                0x0FFFU
/* counters saturate at their all-ones value (no "not available") */
#define MSG_UPTIME_S_MAX             0xFFFFFFU
#define MSG_BUS_OFF_COUNT_MAX        0xFFU
#define MSG_DIAG_COUNT16_MAX         0xFFFFU
/* page 4 */
#define MSG_HSE_FREQ_NA              255U   /* HseFreq_MHz: not measured  */
#define MSG_HSE_FREQ_MAX             254U   /* 25.4 MHz                   */
#define MSG_RESET_CAUSE_MAX          6U
#define MSG_BOR_LEVEL_NA             7U     /* no BOR on this platform    */
#define MSG_LOOPBACK_MAX             3U
#define MSG_STACK_HWM_UNKNOWN        16383U /* StackHighWater_B          */

typedef struct {
	uint8_t crc;
	uint8_t counter;
	uint8_t page;                  /* SquealDiag_Page, MSG_DIAG_PAGE_*      */
	uint16_t fault_bits;           /* MSG_FAULT_*                           */
	/* page 0 */
	uint32_t uptime_s;             /* Uptime_s, 24 bit                      */
	uint8_t bus_off_count;         /* BusOffCount                           */
	/* page 1 */
	uint16_t worst_task_time_us;   /* WorstTaskTime_us                      */
	uint16_t rx_overrun_count;     /* RxOverrunCount                        */
	/* page 2 */
	uint16_t e2e_error_count_speed; /* E2eErrorCountSpeed                   */
	uint16_t e2e_error_count_force; /* E2eErrorCountForce                   */
	/* page 3 */
	uint16_t tx_overflow_count;    /* TxOverflowCount                       */
	uint16_t rx_bad_frame_count;   /* RxBadFrameCount                       */
	/* page 4 */
	uint8_t hse_freq_100khz;       /* HseFreq_MHz raw (0.1 MHz), 255 n/a    */
	uint8_t reset_cause;           /* ResetCause, hal_reset_reason_t        */
	uint8_t bor_level;             /* BorLevel, 7 n/a                       */
	uint8_t loopback_can1;         /* LoopbackCan1                          */
	uint8_t loopback_can2;         /* LoopbackCan2                          */
	uint16_t stack_high_water_b;   /* StackHighWater_B, 16383 unknown       */
} msg_squeal_diag_t;

/*
 * pack: write msg into data[0..dlc-1] (all 8 bytes of data are written,
 * bytes beyond the DLC as 0) and *dlc. Returns SQ_OK, SQ_ERANGE for a
 * field outside its range (data untouched then); a NULL pointer is a
 * programming error (hal_contract_failed, hal.h).
 * SquealDiag packs only the fields of msg->page.
 *
 * unpack: read a received frame into *msg (msg NULL: hal_contract_failed).
 * Returns SQ_OK, SQ_EBADMSG for no data (NULL), a wrong DLC, a counter of 15 or (SquealDiag)
 * an unknown page; *msg is written only on SQ_OK. Values are not range
 * checked beyond that (plausibility is the monitor's job), but the CRC is
 * not checked either: use msg_*_receive() or e2e_p01_check() first.
 * SquealDiag fills the fields of the received page, the others are 0.
 */
#define MSG_CODEC_DECLARE(name)                                                        \
	int msg_##name##_pack(const msg_##name##_t *msg, uint8_t data[8], uint8_t *dlc); \
	int msg_##name##_unpack(const uint8_t *data, uint8_t dlc, msg_##name##_t *msg)
/* msg_disc_speed_pack() / msg_disc_speed_unpack(), and so on */
MSG_CODEC_DECLARE(disc_speed);
MSG_CODEC_DECLARE(pad_force);
MSG_CODEC_DECLARE(squeal_status);
MSG_CODEC_DECLARE(squeal_detail);
MSG_CODEC_DECLARE(squeal_detail2);
MSG_CODEC_DECLARE(squeal_diag);

/*
 * Receive an input: E2E-check the frame (rx is updated whatever happens;
 * data == NULL means "nothing arrived this cycle") and unpack it only when
 * the status is usable. Returns SQ_OK with *msg written (rx->status is OK,
 * INITIAL or OKSOMELOST); SQ_EAGAIN for NONEWDATA; SQ_EBADMSG when the frame
 * must be discarded (rx->status tells why). NULL rx/cfg/msg or an invalid
 * cfg is a programming error (hal_contract_failed).
 * *msg is never written unless SQ_OK is returned.
 */
int msg_disc_speed_receive(const e2e_p01_config_t *cfg, e2e_p01_rx_t *rx,
			   const uint8_t *data, uint8_t dlc,
			   msg_disc_speed_t *msg);
int msg_pad_force_receive(const e2e_p01_config_t *cfg, e2e_p01_rx_t *rx,
			  const uint8_t *data, uint8_t dlc,
			  msg_pad_force_t *msg);

/* ---- descriptors, for host tools (decode/print) and the DBC cross-check - */
#define MSG_SIG_SIGNED  0x01U /* two's complement raw value                  */
#define MSG_SIG_HAS_NA  0x02U /* na_raw is the "not available" value         */
#define MSG_SIG_MUXOR   0x04U /* the multiplexor of its message              */
#define MSG_SIG_MUXED   0x08U /* present only when the multiplexor == mux_value */
#define MSG_SIG_E2E     0x10U /* E2E CRC or counter                          */

/* Where pack()/unpack() keep a signal's raw value in its message's struct. */
#define MSG_FIELD_U8  0U /* uint8_t                                          */
#define MSG_FIELD_U16 1U /* uint16_t                                         */
#define MSG_FIELD_S16 2U /* int16_t                                          */
#define MSG_FIELD_U32 3U /* uint32_t (a value beyond INT32_MAX is out of range) */
#define MSG_FIELD_BIT 4U /* bit `bit` of a uint16_t (SquealDiag's fault_bits) */

typedef struct {
	uint8_t offset;       /* offsetof the field in the message's struct    */
	uint8_t kind;         /* MSG_FIELD_*                                   */
	uint8_t bit;          /* with MSG_FIELD_BIT                            */
} msg_sig_field_t;

typedef struct {
	uint16_t msg_id;      /* CAN identifier of the message                 */
	const char *name;     /* signal name, exactly as in the DBC            */
	const char *unit;     /* as in the DBC ("" for none)                   */
	uint8_t start_bit;    /* Intel: bit number of the LSB (byte*8 + bit)   */
	uint8_t length;       /* bits, 1..31                                   */
	uint8_t flags;        /* MSG_SIG_*                                     */
	uint8_t mux_value;    /* with MSG_SIG_MUXED                            */
	int32_t factor_num;   /* physical = (raw * factor_num + offset_num)    */
	int32_t factor_den;   /*            / factor_den                       */
	int32_t offset_num;
	int32_t raw_min;      /* valid raw range (NA excluded)                 */
	int32_t raw_max;
	int32_t na_raw;       /* with MSG_SIG_HAS_NA                           */
	msg_sig_field_t field; /* its field in the msg_*_t struct              */
} msg_sig_desc_t;

typedef struct {
	uint16_t id;          /* CAN identifier (11 bit)                       */
	const char *name;     /* as in the DBC                                 */
	uint8_t dlc;
	uint16_t period_ms;   /* GenMsgCycleTime                               */
	uint16_t data_id;     /* E2E_DataID                                    */
	uint8_t sig_first;    /* index of its first signal in msg_sig_table    */
	uint8_t sig_count;
} msg_desc_t;

#define MSG_COUNT     6U
#define MSG_SIG_COUNT 53U

extern const msg_desc_t msg_table[MSG_COUNT];
extern const msg_sig_desc_t msg_sig_table[MSG_SIG_COUNT];

/* The message with this identifier, or NULL. */
const msg_desc_t *msg_desc_find(uint16_t id);

/*
 * The name of a SquealState value as the DBC's VAL_ table writes it
 * ("stable", "bistable", "unstable", "not_sliding", "fault"), or NULL for a
 * value the DBC does not name. The one place the bus's state names are
 * spelled (the DBC cross-check compares them with the VAL_ table); host
 * tools print states through it.
 */
const char *msg_squeal_state_name(uint8_t state);

/*
 * The slot of a SquealState value in a per-state table of
 * MSG_SQUEAL_STATE_SLOTS entries: the model's states 0..3 are their own
 * slot, every other value (FAULT, and values the DBC does not name, which
 * a receiver treats as a fault) is slot MSG_SQUEAL_STATE_SLOT_FAULT. Host
 * tools that count time or changes per state index their tables with it.
 */
#define MSG_SQUEAL_STATE_SLOTS      (SQUEAL_STATE_NAMED + 1U)
#define MSG_SQUEAL_STATE_SLOT_FAULT (MSG_SQUEAL_STATE_SLOTS - 1U)
uint32_t msg_squeal_state_slot(uint32_t state);

/*
 * Raw value of one signal in a frame (sign-extended when signed).
 * Returns SQ_OK; SQ_ENOENT for a multiplexed signal that this frame does
 * not carry (other page); SQ_EBADMSG when dlc is not the message's DLC;
 * SQ_EINVAL for a signal of no known message; NULL pointers are a
 * programming error (hal_contract_failed).
 */
int msg_sig_get_raw(const msg_sig_desc_t *sig, const uint8_t *data,
		    uint8_t dlc, int32_t *raw);

#endif /* SQUEAL_MSGS_H */
