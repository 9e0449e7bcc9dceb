/* SPDX-License-Identifier: MIT */
/*
 * hal.h: the whole hardware boundary of the brake-squeal monitor.
 *
 * firmware/ sees the machine only through these plain functions. Every
 * backend (hal/stm32f4/ bare metal, hal/linux/ SocketCAN, the test HAL in
 * tests/support/) implements all of them with the same meaning and the same
 * return codes (sq_status.h: 0 or a negative SQ_E* code). No function blocks:
 * each returns at once or within a documented, bounded time.
 */
#ifndef HAL_H
#define HAL_H

#include <stdbool.h>
#include <stdint.h>

#include "sq_status.h"

/* ---- CAN ---------------------------------------------------------------- */

#define HAL_CAN_MAX_DLEN 8U

/* Flags of a hal_can_frame_t (Zephyr-like: one frame type for every backend). */
#define HAL_CAN_FLAG_EXT (1U << 0) /* 29-bit identifier                      */
#define HAL_CAN_FLAG_RTR (1U << 1) /* remote frame: no data                  */
#define HAL_CAN_FLAG_ERR (1U << 2) /* error frame: id holds the error class  */

typedef struct {
	uint32_t id;          /* 11 or 29 bit identifier                      */
	uint8_t flags;        /* HAL_CAN_FLAG_*                               */
	uint8_t dlc;          /* data length 0..8                             */
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

typedef struct {
	hal_can_state_t state;
	uint8_t tx_error_count;   /* TEC */
	uint8_t rx_error_count;   /* REC */
	uint32_t bus_off_count;   /* bus-off events since start (cumulative)    */
	uint32_t rx_overruns;     /* frames lost before firmware saw them       */
	uint32_t tx_dropped;      /* frames the backend had to give up          */
	uint32_t error_frames;    /* error frames / controller problems seen    */
} hal_can_status_t;

/*
 * Queue one frame for sending. Never blocks.
 * Returns SQ_OK, SQ_ENOBUFS (TX queue full: nothing queued),
 * SQ_ENETUNREACH (bus-off), SQ_ENETDOWN (stopped), SQ_EINVAL (bad frame).
 */
int hal_can_send(const hal_can_frame_t *frame);

/*
 * Take the oldest received frame, if any. Never blocks.
 * Returns SQ_OK (frame filled, with timestamp), SQ_EAGAIN (nothing pending),
 * SQ_ENETDOWN (stopped), SQ_EINVAL (NULL).
 */
int hal_can_receive(hal_can_frame_t *frame);

/* Returns SQ_OK with *status filled, SQ_EINVAL (NULL). */
int hal_can_get_status(hal_can_status_t *status);

/*
 * Run the controller at this bit rate (kbit/s, from calibration). A no-op
 * when it already runs at that rate; otherwise the controller restarts
 * (pending TX frames are dropped, the RX filter is reset: set it after).
 * Returns SQ_OK; SQ_EINVAL (the clock cannot make that rate exactly enough);
 * SQ_EAGAIN (the controller did not start: HAL_FAULT_CAN_INIT is raised);
 * SQ_ENOTSUP where the bit rate belongs to the OS (Linux: `ip link set can0
 * type can bitrate ...`).
 */
int hal_can_set_bitrate(uint32_t bitrate_kbps);

/*
 * Accept only these standard (11-bit) identifiers from now on (in hardware
 * where the controller can). count <= HAL_CAN_MAX_FILTERS.
 * Returns SQ_OK, SQ_EINVAL (too many / bad id), SQ_ENOTSUP.
 */
#define HAL_CAN_MAX_FILTERS 8U
int hal_can_set_rx_filter(const uint32_t *ids, uint32_t count);

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
/* 1 KiB flash page of the F103 minus the slot header (16): calib v2 with
 * the input map is 989 bytes */
#define HAL_CALIB_MAX_LEN 1008U
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
uint32_t hal_platform_faults(void);

#endif /* HAL_H */
