/* SPDX-License-Identifier: MIT */
/*
 * hal_linux.h: the Linux backend of hal/hal.h, and its set-up functions.
 *
 * CAN is one SocketCAN CAN_RAW socket per bus, each on a named interface
 * (vcan0, can0, a PEAK/Kvaser/slcan adapter ...): bus 0 is the firmware's
 * first bus, bus 1 (if opened) its second. Nothing here needs root or a
 * capability: the interface must exist and be up already (ip link ... up is
 * the administrator's job, as is `ip link set can0 type can listen-only on`
 * for a bus the firmware only listens to). This backend is linked instead
 * of the in-memory one (hal/vbus); nothing switches at run time. Pieces:
 *   hal_linux_can.c    CAN sockets, filters, error frames, timestamps, TX retry
 *   hal_linux_time.c   hal_time_us, hal_cycles (CLOCK_MONOTONIC)
 *   hal_linux_idle.c   hal_idle_until, SIGINT/SIGTERM, software watchdog
 *   hal_linux_calib.c  calibration file, reset reason
 *   hal_linux.c        last-error text, platform fault bits
 *
 * Single-threaded: call everything from the firmware's thread (the signal
 * handlers only set a flag and write one byte to a pipe).
 *
 * A Linux ECU main, in outline:
 *	static volatile bool stop;
 *	hal_linux_install_signal_handlers(&stop);   SIGINT/SIGTERM end the loop
 *	hal_linux_set_calib_path("squeal.cal");
 *	if (hal_linux_open(0, "vcan0", NULL) != SQ_OK)
 *		fprintf(stderr, "%s\n", hal_linux_strerror()), exit(1);
 *	squeal_main(&stop);                          poll + hal_idle_until
 *	hal_linux_close();
 */
#ifndef HAL_LINUX_H
#define HAL_LINUX_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "hal.h"

/* ---- CAN ---------------------------------------------------------------- */

typedef struct {
	/* SO_RCVBUF / SO_SNDBUF in bytes; 0 keeps the kernel's default. The
	 * kernel doubles the value and enforces a minimum. */
	int rcvbuf_bytes;
	int sndbuf_bytes;
	/* TX back-off when the kernel queue is full: at most tx_max_tries
	 * attempts within tx_budget_us in total (0 = defaults: 3 tries,
	 * 1000 us). */
	uint32_t tx_max_tries;
	uint32_t tx_budget_us;
} hal_linux_can_opts_t;

/*
 * Open bus's CAN_RAW socket on ifname (bus < HAL_CAN_BUSES; bus 0 always
 * exists, bus 1 exists for hal.h once an interface was named for it here,
 * SQ_ENODEV until then): all standard and extended data frames
 * pass until hal_can_set_rx_filter(); error frames (bus-off, controller
 * problems, restarts, protocol/ACK/transceiver errors, counters; not lost
 * arbitration) are on. CAN FD is on when the interface's MTU is 72
 * (CANFD_MTU: `ip link set can0 mtu 72`, for a real adapter with `type can
 * bitrate ... dbitrate ... fd on`); at MTU 16 it stays off, said once per
 * interface on stderr ("can0: MTU 16, CAN FD off (ip link set can0 mtu
 * 72)"), and FD sends answer SQ_ENOTSUP. opts may be NULL for the defaults.
 * Re-opening closes that bus's previous socket first and asks the MTU
 * again; the bus's mode (hal_can_set_mode) stays.
 * Returns SQ_OK, or (with hal_linux_strerror() saying what and what to do):
 *   SQ_ENOTSUP   this kernel has no CAN (socket(PF_CAN) EAFNOSUPPORT or
 *                EPROTONOSUPPORT)
 *   SQ_ENOENT    no interface of that name
 *   SQ_ENETDOWN  the interface is down
 *   SQ_EINVAL    bad name, or not a CAN interface (e.g. "lo")
 *   SQ_EIO       permission denied or another system error
 */
int hal_linux_open(uint8_t bus, const char *ifname, const hal_linux_can_opts_t *opts);

/* Close every bus's socket (hal_can_* then return SQ_ENETDOWN). Safe to
 * repeat. */
void hal_linux_close(void);

/* bus's socket, for a caller's own poll() (-1 when closed). */
int hal_linux_can_fd(uint8_t bus);

/* Whether bus's open socket carries CAN FD frames (the interface's MTU was
 * 72 at hal_linux_open); false when closed. */
bool hal_linux_can_fd_on(uint8_t bus);

/* Counters beyond hal_can_status_t, for tests and the host tools. */
typedef struct {
	uint64_t rx_frames;      /* data/RTR frames handed to the caller        */
	uint64_t rx_err_frames;  /* error frames handed to the caller           */
	uint64_t tx_frames;      /* frames the kernel accepted                  */
	uint64_t tx_retries;     /* extra attempts after ENOBUFS/EAGAIN         */
	uint64_t tx_dropped;     /* frames given up after the back-off budget   */
	uint64_t tx_enobufs;     /* attempts refused: queueing discipline full  */
	uint64_t tx_eagain;      /* attempts refused: socket send buffer full   */
	uint64_t rx_kernel_drops; /* SO_RXQ_OVFL: socket queue overflows        */
	uint64_t rx_ctrl_overflows; /* controller RX overflow error frames      */
	uint64_t rx_skipped;     /* frames the HAL cannot hand over (CAN XL, a
				  * length no frame of its format has): ignored */
	uint64_t ts_fallbacks;   /* frames without a kernel timestamp           */
	uint32_t tx_worst_us;    /* longest hal_can_send() call                  */
} hal_linux_can_stats_t;

void hal_linux_can_get_stats(uint8_t bus, hal_linux_can_stats_t *stats);

/* Back to accepting every data frame (undoes hal_can_set_rx_filter). */
int hal_linux_can_accept_all(uint8_t bus);

/* ---- errors --------------------------------------------------------------- */

/* Text of the last failure of hal_linux_* or hal_* set-up calls ("" if none;
 * a successful hal_linux_open() clears it):
 * one line, meant for a user, naming the interface/file and the remedy. */
const char *hal_linux_strerror(void);

/* ---- time, idle, signals, watchdog ----------------------------------------- */

/*
 * SIGINT and SIGTERM set *stop to true and wake hal_idle_until() at once
 * (a self-pipe, so a signal that arrives just before poll() is not lost).
 * SIGPIPE is ignored (a closed stdout must not kill the ECU mid-frame).
 * Returns SQ_OK or SQ_EIO.
 */
int hal_linux_install_signal_handlers(volatile bool *stop);

/* The software watchdog (hal_watchdog_start/kick): there is no reset line on
 * a Linux process, so it reports. hal_idle_until() and this function check
 * the deadline; an expiry is counted, printed once on stderr and sticky until
 * the next hal_watchdog_start(). */
bool hal_linux_watchdog_expired(void);
uint32_t hal_linux_watchdog_expiries(void);

/* When on, an expiry also sets the stop flag given to
 * hal_linux_install_signal_handlers(), so squeal_main() returns and the
 * program can exit with an error: the Linux analogue of a watchdog reset.
 * Default off (report only). */
void hal_linux_watchdog_stop_on_expiry(bool on);

/* Convert a CLOCK_REALTIME instant (kernel socket timestamps) to the
 * hal_time_us() base, with the offset between the clocks read now. */
uint64_t hal_linux_realtime_to_mono_us(int64_t real_s, int64_t real_ns);

/* ---- calibration, reset ---------------------------------------------------- */

/* The file that holds the calibration block (copied; NULL/"" = none: read
 * gives SQ_ENOENT, write SQ_EIO). Returns SQ_OK or SQ_EINVAL (too long). */
int hal_linux_set_calib_path(const char *path);

/* What hal_reset_reason() reports (default HAL_RESET_POWER_ON: a process
 * start is a power-on; a supervisor that restarts the ECU after a watchdog
 * report may say HAL_RESET_WATCHDOG or HAL_RESET_SOFTWARE here). */
void hal_linux_set_reset_reason(hal_reset_reason_t reason);

/* ---- internal, shared between the hal_linux_*.c files ----------------------- */

void hal_linux_set_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void hal_linux_add_fault(uint32_t fault_bits);
int hal_linux_signal_fd(void);

#endif /* HAL_LINUX_H */
