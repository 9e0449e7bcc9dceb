/* SPDX-License-Identifier: MIT */
/*
 * hal_linux_idle.c: sleeping until the next deadline, the shutdown signals,
 * and the software watchdog.
 *
 * hal_idle_until() is one ppoll() on every bus's CAN socket and the read end of a
 * self-pipe: it wakes on a frame (or a socket error such as ENETDOWN), on
 * SIGINT/SIGTERM (the handler writes a byte to the pipe, so a signal that
 * lands just before ppoll() still wakes it), or at the deadline (ppoll takes
 * a timespec: microsecond resolution, no rounding up to milliseconds).
 *
 * Watchdog: a Linux process has no reset line, and a timer signal that
 * killed the process would hide the cause. The watchdog is therefore a
 * deadline checked on every hal_idle_until() and hal_linux_watchdog_expired()
 * call: a missed kick is detected no later than the loop's next idle, is
 * counted, reported once on stderr, and stays set for the host program to
 * act on (the ECU host-sim exits with an error, as a reset would).
 */
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "hal_linux.h"

static int wake_pipe[2] = { -1, -1 };
static volatile bool *stop_flag;

static bool wdg_running;
static uint32_t wdg_timeout_us;
static uint64_t wdg_last_kick_us;
static bool wdg_expired;
static uint32_t wdg_expiries;
static bool wdg_stop_on_expiry;

static void on_stop_signal(int signo)
{
	int saved_errno = errno;
	const char byte = 1;

	(void)signo;
	if (stop_flag != NULL) {
		/* A lock-free store of a bool: what a handler may do. */
		*stop_flag = true;
	}
	/* Non-blocking: a full pipe already means "wake up". */
	(void)!write(wake_pipe[1], &byte, 1U);
	errno = saved_errno;
}

int hal_linux_install_signal_handlers(volatile bool *stop)
{
	struct sigaction sa;

	if (wake_pipe[0] < 0 && pipe2(wake_pipe, O_NONBLOCK | O_CLOEXEC) != 0) {
		hal_linux_set_error("signal set-up: pipe2: %s", strerror(errno));
		return SQ_EIO;
	}
	stop_flag = stop;
	memset(&sa, 0, sizeof(sa));
	sa.sa_handler = on_stop_signal;
	/* No SA_RESTART: a blocking call in the host program returns EINTR. */
	sa.sa_flags = 0;
	if (sigemptyset(&sa.sa_mask) != 0 || sigaction(SIGINT, &sa, NULL) != 0
	    || sigaction(SIGTERM, &sa, NULL) != 0) {
		hal_linux_set_error("signal set-up: sigaction: %s", strerror(errno));
		return SQ_EIO;
	}
	sa.sa_handler = SIG_IGN;
	if (sigaction(SIGPIPE, &sa, NULL) != 0) {
		hal_linux_set_error("signal set-up: sigaction(SIGPIPE): %s", strerror(errno));
		return SQ_EIO;
	}
	return SQ_OK;
}

int hal_linux_signal_fd(void)
{
	return wake_pipe[0];
}

static void drain_wake_pipe(void)
{
	char buf[16];
	int i;

	/* Bounded: the pipe holds at most a few bytes per signal burst. */
	for (i = 0; i < 64; i++) {
		if (read(wake_pipe[0], buf, sizeof(buf)) <= 0) {
			break;
		}
	}
}

static void watchdog_check(uint64_t now_us)
{
	if (!wdg_running || wdg_expired) {
		return;
	}
	if (now_us - wdg_last_kick_us > wdg_timeout_us) {
		wdg_expired = true;
		wdg_expiries++;
		(void)fprintf(stderr, "hal_linux: watchdog expired: no kick for %llu us (timeout %u us)\n",
			      (unsigned long long)(now_us - wdg_last_kick_us), wdg_timeout_us);
		if (wdg_stop_on_expiry && stop_flag != NULL) {
			*stop_flag = true;
		}
	}
}

void hal_idle_until(uint64_t deadline_us)
{
	struct pollfd fds[HAL_CAN_BUSES + 1U];
	nfds_t n = 0;
	uint64_t now_us = hal_time_us();
	uint64_t wait_us;
	struct timespec ts;
	uint8_t bus;

	watchdog_check(now_us);
	if (stop_flag != NULL && *stop_flag) {
		/* The signal's byte must not wake a later idle early. */
		if (wake_pipe[0] >= 0) {
			drain_wake_pipe();
		}
		return;
	}
	if (deadline_us <= now_us) {
		return;
	}
	wait_us = deadline_us - now_us;
	/* Wake at least once a second: the watchdog is checked here. */
	if (wait_us > 1000000U) {
		wait_us = 1000000U;
	}
	for (bus = 0U; bus < HAL_CAN_BUSES; bus++) {
		const int can_fd = hal_linux_can_fd(bus);

		if (can_fd >= 0) {
			fds[n].fd = can_fd;
			fds[n].events = POLLIN;
			fds[n].revents = 0;
			n++;
		}
	}
	if (wake_pipe[0] >= 0) {
		fds[n].fd = wake_pipe[0];
		fds[n].events = POLLIN;
		fds[n].revents = 0;
		n++;
	}
	ts.tv_sec = (time_t)(wait_us / 1000000U);
	ts.tv_nsec = (long)((wait_us % 1000000U) * 1000U);
	/* EINTR (a signal) is a wake-up like any other: nothing to retry. */
	if (ppoll(n > 0U ? fds : NULL, n, &ts, NULL) > 0 && wake_pipe[0] >= 0) {
		drain_wake_pipe();
	}
	watchdog_check(hal_time_us());
}

int hal_watchdog_start(uint32_t timeout_ms)
{
	if (timeout_ms == 0U || timeout_ms > 60000U) {
		return SQ_EINVAL;
	}
	wdg_timeout_us = timeout_ms * 1000U;
	wdg_last_kick_us = hal_time_us();
	wdg_running = true;
	/* A new start is a new watchdog (as after a reset); the count stays. */
	wdg_expired = false;
	return SQ_OK;
}

void hal_watchdog_kick(void)
{
	wdg_last_kick_us = hal_time_us();
}

bool hal_linux_watchdog_expired(void)
{
	watchdog_check(hal_time_us());
	return wdg_expired;
}

uint32_t hal_linux_watchdog_expiries(void)
{
	return wdg_expiries;
}

void hal_linux_watchdog_stop_on_expiry(bool on)
{
	wdg_stop_on_expiry = on;
}
