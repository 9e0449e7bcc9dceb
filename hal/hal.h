/* SPDX-License-Identifier: MIT */
/*
 * hal.h: the whole hardware boundary of the brake-squeal monitor.
 *
 * firmware/ sees the machine only through these plain functions. Every
 * backend (hal/stm32f4/ bare metal, hal/linux/ SocketCAN, hal/vbus/ in
 * memory; one per program, chosen at link time) implements all of them with
 * the same meaning and the same return codes (sq_status.h: 0 or a negative
 * SQ_E* code); tests/hal/conformance.c checks that on each. No function
 * blocks: each returns at once or within a documented, bounded time.
 */
#ifndef HAL_H
#define HAL_H

#include <stdbool.h>
#include <stdint.h>

#include "sq_contract.h"
#include "sq_status.h"

/* ---- CAN ---------------------------------------------------------------- */

/*
 * Buses. Every CAN call names its bus: 0 .. HAL_CAN_BUSES-1 (the ECU's CAN1
 * and CAN2; on Linux the interfaces given to the backend, e.g. can0 and can1).
 * A bus index >= HAL_CAN_BUSES, or a NULL pointer, is a programming error:
 * it goes to hal_contract_failed() and never returns an error code. A bus
 * that is a valid index but does not exist on this platform (the STM32F103's
 * bus 1, a Linux backend opened with one interface) answers SQ_ENODEV.
 */
#define HAL_CAN_BUSES 2U

/* CAN FD (ISO 11898-1:2015): up to 64 data bytes. A frame's dlc field holds
 * its data length in bytes; above 8 only the lengths of DLC codes 9..15 exist
 * (12, 16, 20, 24, 32, 48, 64), any other length is malformed. */
#define HAL_CAN_CLASSIC_MAX_DLEN 8U
#define HAL_CAN_FD_MAX_DLEN 64U

/*
 * The data bytes a frame holds: a property of the backend build, fixed at
 * compile time. 64 on the host builds (hal/linux, hal/vbus, every host and
 * test program); 8 in the ECU images, whose controllers (bxCAN on the
 * STM32F405/407 and STM32F103) carry classic frames only and whose RAM holds
 * many frames: mk/target.mk builds them with -DHAL_CAN_CLASSIC_ONLY. A
 * backend that cannot carry FD frames (bxCAN; SocketCAN on an interface of
 * MTU 16) refuses them with SQ_ENOTSUP, counted, never truncated.
 */
#if defined(HAL_CAN_CLASSIC_ONLY)
#define HAL_CAN_MAX_DLEN HAL_CAN_CLASSIC_MAX_DLEN
#else
#define HAL_CAN_MAX_DLEN HAL_CAN_FD_MAX_DLEN
#endif

/* Flags of a hal_can_frame_t (Zephyr-like: one frame type for every backend).
 * A well-formed frame (hal_can_common.h, the one check): BRS and ESI only
 * with FDF; FDF never with RTR or ERR; without FDF at most 8 data bytes,
 * with FDF a DLC-code length (0..8, 12, 16, 20, 24, 32, 48, 64). */
#define HAL_CAN_FLAG_EXT (1U << 0) /* 29-bit identifier                      */
#define HAL_CAN_FLAG_RTR (1U << 1) /* remote frame: no data                  */
#define HAL_CAN_FLAG_ERR (1U << 2) /* error frame: id holds the error class  */
#define HAL_CAN_FLAG_FDF (1U << 3) /* CAN FD frame format (FDF bit)          */
#define HAL_CAN_FLAG_BRS (1U << 4) /* FD: bit rate switch in the data phase  */
#define HAL_CAN_FLAG_ESI (1U << 5) /* FD: sender was error passive           */

/* Data length in bytes of a DLC code 0..15 (codes 9..15: FD lengths). */
static inline uint8_t hal_can_dlc_to_len(uint8_t dlc_code)
{
	static const uint8_t len_of_code[16] = { 0U, 1U, 2U, 3U, 4U, 5U, 6U, 7U, 8U,
						 12U, 16U, 20U, 24U, 32U, 48U, 64U };
	return len_of_code[dlc_code & 0x0FU];
}

/* DLC code 0..15 of a data length in bytes; 0xFF where no DLC code has
 * exactly that length (13 bytes, 65 bytes: malformed). */
static inline uint8_t hal_can_len_to_dlc(uint8_t len)
{
	uint8_t code;
	uint8_t found = 0xFFU;

	for (code = 0U; (code < 16U) && (found == 0xFFU); code++) {
		if (hal_can_dlc_to_len(code) == len) {
			found = code;
		}
	}
	return found;
}

#define HAL_CAN_STD_ID_MAX 0x7FFUL
#define HAL_CAN_EXT_ID_MAX 0x1FFFFFFFUL

typedef struct {
	uint32_t id;          /* 11 or 29 bit identifier                      */
	uint8_t flags;        /* HAL_CAN_FLAG_*                               */
	uint8_t dlc;          /* data length in bytes: 0..8, or with FDF a
			       * DLC-code length up to HAL_CAN_MAX_DLEN      */
	uint8_t data[HAL_CAN_MAX_DLEN];
	uint64_t timestamp_us; /* receive time on hal_time_us()'s clock       */
} hal_can_frame_t;

/* Controller state, as CAN defines it (ISO 11898-1 fault confinement). */
typedef enum {
	HAL_CAN_STATE_ERROR_ACTIVE = 0,
	HAL_CAN_STATE_ERROR_WARNING = 1, /* a counter >= 96                    */
	HAL_CAN_STATE_ERROR_PASSIVE = 2, /* a counter >= 128                   */
	HAL_CAN_STATE_BUS_OFF = 3,       /* TEC > 255, not sending              */
	HAL_CAN_STATE_STOPPED = 4        /* not started / interface down        */
} hal_can_state_t;

/*
 * Mode of one bus. LISTEN_ONLY: this node puts nothing on that bus, no data
 * frame, no ACK bit, no error frame (bxCAN silent mode; on Linux the HAL
 * refuses every send and the interface itself is set listen-only by the
 * administrator: `ip link set can0 type can listen-only on`). Receiving is
 * unchanged.
 */
typedef enum {
	HAL_CAN_MODE_NORMAL = 0,
	HAL_CAN_MODE_LISTEN_ONLY = 1
} hal_can_mode_t;

typedef struct {
	hal_can_state_t state;
	hal_can_mode_t mode;
	uint8_t tx_error_count;   /* TEC */
	uint8_t rx_error_count;   /* REC */
	uint32_t bus_off_count;   /* bus-off events since start (cumulative)    */
	uint32_t state_changes;   /* state transitions since start (cumulative) */
	uint32_t rx_overruns;     /* frames lost before firmware saw them       */
	uint32_t tx_dropped;      /* frames the backend had to give up          */
	uint32_t tx_refused_listen_only; /* sends refused: bus is listen-only  */
	uint32_t error_frames;    /* error frames / controller problems seen    */
	uint32_t fd_unsupported;  /* FD frames refused: this bus carries classic
				   * frames only (SQ_ENOTSUP)                   */
} hal_can_status_t;

/*
 * One acceptance filter: a received data or remote frame passes when
 * (frame.id & mask) == (id & mask) and its kind (standard or extended,
 * HAL_CAN_FLAG_EXT in flags) is the filter's. mask 0 with the EXT flag
 * clear passes every standard frame. Error frames are never filtered.
 */
typedef struct {
	uint32_t id;
	uint32_t mask;
	uint8_t flags;        /* HAL_CAN_FLAG_EXT or 0                        */
} hal_can_filter_t;

#define HAL_CAN_MAX_FILTERS 14U /* per bus (bxCAN: 28 banks split by CAN2SB) */

/* The largest identifier of a frame or filter with these HAL_CAN_FLAG_*
 * (11 or 29 bits), for every backend's range checks. */
static inline uint32_t hal_can_id_max(uint8_t flags)
{
	return ((flags & HAL_CAN_FLAG_EXT) != 0U) ? (uint32_t)HAL_CAN_EXT_ID_MAX :
		(uint32_t)HAL_CAN_STD_ID_MAX;
}

/*
 * Queue one frame (classic, or FD with FDF and BRS/ESI as given) for
 * sending on bus. Never blocks. Returns, in this order of checks:
 * SQ_EINVAL (malformed frame: a length above 8 without FDF, an FDF length
 * that is no DLC code's, FDF with RTR, BRS or ESI without FDF, an
 * identifier out of range for its kind, ERR or an undefined flag bit),
 * SQ_ENODEV, SQ_ENOTSUP (an FD frame on a bus that carries classic frames
 * only: bxCAN, SocketCAN at MTU 16; nothing sent, counted in
 * fd_unsupported), SQ_EPERM (the bus is listen-only: nothing sent, counted
 * in tx_refused_listen_only), then SQ_ENETDOWN (stopped), SQ_ENETUNREACH
 * (bus-off), SQ_ENOBUFS (TX queue full: nothing queued) or SQ_OK. Every
 * backend admits the frame first with one function (hal_can_common.h), so
 * a malformed frame gets SQ_EINVAL whatever the bus's state.
 */
int hal_can_send(uint8_t bus, const hal_can_frame_t *frame);

/*
 * Take the oldest received frame of bus, if any. Never blocks.
 * Returns SQ_OK (frame filled, with timestamp: classic, or FD with FDF and
 * the frame's BRS/ESI, its dlc the data length, up to HAL_CAN_MAX_DLEN;
 * an error frame has ERR and 8 bytes), SQ_EAGAIN (nothing pending),
 * SQ_ENETDOWN (stopped), SQ_ENODEV. A backend hands over well-formed frames
 * only: what its controller or kernel gives otherwise is dropped, counted.
 */
int hal_can_receive(uint8_t bus, hal_can_frame_t *frame);

/* Returns SQ_OK with *status filled (the counters cumulative, the mode the
 * firmware set), SQ_ENODEV. */
int hal_can_get_status(uint8_t bus, hal_can_status_t *status);

/*
 * Run bus at this bit rate (kbit/s, from calibration). A no-op when it
 * already runs at that rate; otherwise the controller restarts (pending TX
 * frames are dropped, the RX filters are reset: set them after).
 * Returns SQ_OK; SQ_EINVAL (the clock cannot make that rate exactly: the
 * controller is left untouched, running as before); SQ_EAGAIN (the
 * controller did not start: HAL_FAULT_CAN_INIT is raised); SQ_ENOTSUP where
 * the bit rate belongs to the OS (Linux: `ip link set can0 type can bitrate
 * ...`, with FD also `dbitrate ... fd on`); SQ_ENODEV. The rate is the
 * nominal (arbitration) one; no classic-only controller has a data phase.
 */
int hal_can_set_bitrate(uint8_t bus, uint32_t bitrate_kbps);

/*
 * Accept only frames that pass one of these filters from now on (in
 * hardware where the controller can). count 0 accepts nothing but error
 * frames. Classic and FD frames pass alike (the id and its kind decide).
 * count > HAL_CAN_MAX_FILTERS is a programming error.
 * Returns SQ_OK, SQ_EINVAL (an id or mask out of range for its kind, a
 * flag other than EXT),
 * SQ_ENOTSUP, SQ_ENODEV.
 */
int hal_can_set_rx_filter(uint8_t bus, const hal_can_filter_t *filters,
			  uint32_t count);

/*
 * Set the bus's mode (default NORMAL). On the ECU this restarts the
 * controller like a bit-rate change (set filters after it). The mode does
 * not change which frame formats the bus carries.
 * Returns SQ_OK, SQ_EAGAIN (controller did not restart), SQ_ENODEV.
 */
int hal_can_set_mode(uint8_t bus, hal_can_mode_t mode);

/* ---- time ---------------------------------------------------------------- */

/* Monotonic microseconds since an arbitrary start; never goes back. */
uint64_t hal_time_us(void);

/*
 * Sleep (WFI on the ECU, clock_nanosleep/poll on Linux) until deadline_us or
 * until a frame or another event may need attention, whichever is first.
 * May return early; never returns later than deadline_us + one tick.
 */
void hal_idle_until(uint64_t deadline_us);

/*
 * A free-running cycle counter for task timing (DWT CYCCNT on the ECU,
 * nanoseconds on Linux, instructions or ticks in tests) and its rate.
 */
uint32_t hal_cycles(void);
uint32_t hal_cycles_per_us(void);

/* ---- watchdog ------------------------------------------------------------ */

/* Start the watchdog with the given timeout; SQ_OK, SQ_EINVAL, SQ_ENOTSUP. */
int hal_watchdog_start(uint32_t timeout_ms);
void hal_watchdog_kick(void);

/* ---- calibration storage ------------------------------------------------- */

/*
 * Non-volatile storage for one calibration block (opaque bytes to the HAL;
 * firmware/monitor/calib.c owns the format, version and CRC).
 * read:  SQ_OK (len bytes copied), SQ_ENOENT (nothing stored / erased),
 *        SQ_EINVAL (len > HAL_CALIB_MAX_LEN or NULL), SQ_EIO.
 * write: SQ_OK, SQ_EINVAL, SQ_EIO (program or verify failed). A write that
 *        is interrupted (reset, power loss) leaves either the old or the new
 *        block readable, never a mix; the CRC inside the block proves which.
 */
/* The F103's 2 KiB slot (two 1 KiB pages) minus the slot header (16):
 * calib v3 (64-bit decimals, two selectors, torque share) is 1440 bytes */
#define HAL_CALIB_MAX_LEN 2032U
int hal_calib_read(uint8_t *buf, uint32_t len);
int hal_calib_write(const uint8_t *buf, uint32_t len);

/* ---- reset --------------------------------------------------------------- */

typedef enum {
	HAL_RESET_POWER_ON = 0,
	HAL_RESET_PIN = 1,
	HAL_RESET_WATCHDOG = 2,
	HAL_RESET_SOFTWARE = 3,
	HAL_RESET_FAULT = 4, /* a fault handler recorded a cause and reset */
	HAL_RESET_BROWNOUT = 5,
	HAL_RESET_UNKNOWN = 6
} hal_reset_reason_t;

hal_reset_reason_t hal_reset_reason(void);

/* ---- platform faults ----------------------------------------------------- */

/* Faults the platform found at start-up or since (bits, cumulative):
 * the monitor copies them into SquealDiag. */
#define HAL_FAULT_CLOCK_FALLBACK (1U << 0) /* HSE/PLL failed: running on HSI */
#define HAL_FAULT_CAN_INIT       (1U << 1) /* CAN controller did not start   */
#define HAL_FAULT_CALIB_STORAGE  (1U << 2) /* calibration storage unusable   */
#define HAL_FAULT_SELFTEST       (1U << 3) /* a bring-up self-test check failed (BOR level, stack) */
uint32_t hal_platform_faults(void);

/* ---- bring-up self-test ---------------------------------------------------- */

/* Result of one controller's silent-loopback test (a frame sent to itself
 * while nothing reaches the bus): hal_selftest_t.loopback[bus]. */
#define HAL_LOOPBACK_PASS        0U /* the frame came back unchanged           */
#define HAL_LOOPBACK_FAIL        1U /* the controller ran, the frame did not   */
#define HAL_LOOPBACK_UNAVAILABLE 2U /* controller not running (no clock, QEMU) */
#define HAL_LOOPBACK_NO_BUS      3U /* the chip has no such controller         */

#define HAL_SELFTEST_NOT_MEASURED 0xFFFFFFFFUL
#define HAL_SELFTEST_NO_BOR 0xFFU

/* What the platform measured about itself at this start, before the
 * firmware ran (the ECU's bring-up self-test). The reset cause is
 * hal_reset_reason(). */
typedef struct {
	uint32_t hse_hz;           /* measured crystal; 0 none; NOT_MEASURED  */
	uint32_t stack_high_water_prev_b; /* previous run's deepest stack use;
					   * NOT_MEASURED after power-on */
	uint8_t bor_level;         /* brown-out reset level 0..3 (3: VDD >= 2.7 V);
				    * HAL_SELFTEST_NO_BOR: the chip has none */
	uint8_t loopback[HAL_CAN_BUSES]; /* HAL_LOOPBACK_* per bus             */
	bool failed;               /* a check failed (its HAL_FAULT_* bit is set) */
} hal_selftest_t;

/* SQ_OK with *result filled; SQ_ENOTSUP where the platform has no such
 * test (Linux, the in-memory bus). */
int hal_selftest(hal_selftest_t *result);

/* ---- contracts ----------------------------------------------------------- */

/* HAL_REQUIRE() and hal_contract_failed(), the one handler for programming
 * errors (a NULL pointer, a bad bus index, a bad configuration), never for
 * bad data: sq_contract.h, included above. */

#endif /* HAL_H */
