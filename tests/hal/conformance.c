/* SPDX-License-Identifier: MIT */
/*
 * conformance.c: the one HAL conformance suite. The same source runs on
 * every backend, linked with that backend's harness (conformance_backend.h):
 * the in-memory bus (conf_hal_vbus_can.c, make test), SocketCAN on vcan0 + vcan1 in
 * the QEMU guest (conf_hal_linux_can.c, tests/system/vcan/run-conformance.sh) and bxCAN
 * on simulated registers (conf_bxcan.c). mk/hal-conformance.mk links it.
 *
 * It talks to the backend only through hal/hal.h; the harness is the other
 * side of the wire. Per bus it checks: filter semantics (standard, extended,
 * masks, none), receive order, monotonic timestamps, error frames reported,
 * TX queue-full error and recovery, bus-off reported, sending, the one
 * frame rule (an undefined or error flag, DLC > 8, an id out of range:
 * SQ_EINVAL everywhere, also in listen-only), listen-only (nothing sent,
 * refusals counted, receiving goes on, the other bus keeps working, the
 * mode survives a bus-off), that no frame of one bus appears on the
 * other, SQ_ENODEV for a bus the backend lacks, and that a bad bus index or
 * NULL goes to the contract handler. CAN FD: malformed FD frames (a length
 * no DLC code has, FDF with RTR, BRS/ESI without FDF, more than 8 bytes
 * without FDF) are SQ_EINVAL everywhere; on a bus that carries FD frames
 * every DLC code 9..15 (64 bytes included) goes both ways with BRS/ESI
 * kept, classic and FD frames mixed in order; on a classic-only bus an FD
 * frame is refused with SQ_ENOTSUP, counted, nothing sent, and the round
 * trips are a SKIP. Every check prints one line:
 *   PASS  hal-conformance [vbus] bus 0: ...
 *   FAIL  hal-conformance [vbus] bus 0: ... (what was seen)
 *   SKIP: hal-conformance [socketcan] bus 0: ... (why)
 * and the run ends with "RESULT: N passed, M failed, K skipped".
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "conformance_backend.h"
#include "test_frame.h"
#include "conformance_contract.h"

#define SETTLE_US 20000U  /* time for frames to cross the wire           */
#define MAX_DRAIN 64U     /* bound on frames read back per check         */
#define MAX_FILL 256U     /* bound on sends while the TX path is blocked */

static uint32_t n_pass;
static uint32_t n_fail;
static uint32_t n_skip;

static void report(bool ok, uint8_t bus, const char *what, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));

static void report(bool ok, uint8_t bus, const char *what, const char *fmt, ...)
{
	va_list ap;

	printf("%s  hal-conformance [%s] bus %u: %s", ok ? "PASS" : "FAIL", conf_backend_name(),
	       (unsigned int)bus, what);
	if (!ok) {
		printf(" (");
		va_start(ap, fmt);
		(void)vprintf(fmt, ap);
		va_end(ap);
		printf(")");
		n_fail++;
	} else {
		n_pass++;
	}
	printf("\n");
}

static void skip(uint8_t bus, const char *what, const char *why)
{
	printf("SKIP: hal-conformance [%s] bus %u: %s (%s)\n", conf_backend_name(), (unsigned int)bus,
	       what, why);
	n_skip++;
}

/* A fresh backend for one check; a failed set-up is that check's FAIL. */
static bool set_up(uint8_t bus, const char *what)
{
	if (conf_backend_setup() != SQ_OK) {
		report(false, bus, what, "harness set-up failed");
		return false;
	}
	return true;
}

static hal_can_frame_t frame(uint32_t id, uint8_t flags, uint8_t dlc, uint8_t seed)
{
	return test_frame(id, flags, dlc, seed, 17U);
}

static bool same_frame(const hal_can_frame_t *a, const hal_can_frame_t *b)
{
	return (a->id == b->id) && (a->flags == b->flags) && (a->dlc == b->dlc) &&
	       (memcmp(a->data, b->data, a->dlc) == 0);
}

static bool same_frames(const hal_can_frame_t *got, uint32_t n, const hal_can_frame_t *want, uint32_t m)
{
	uint32_t i;
	bool same = (n == m);

	for (i = 0U; same && (i < n); i++) {
		same = same_frame(&got[i], &want[i]);
	}
	return same;
}

typedef int (*take_fn_t)(uint8_t bus, hal_can_frame_t *frame);

/* Every frame `take` gives for bus, oldest first (at most max kept). */
static uint32_t take_all(take_fn_t take, uint8_t bus, hal_can_frame_t *out, uint32_t max)
{
	hal_can_frame_t scratch;
	uint32_t n = 0U;
	uint32_t i;

	for (i = 0U; i < MAX_DRAIN; i++) {
		hal_can_frame_t *f = (n < max) ? &out[n] : &scratch;

		if (take(bus, f) != SQ_OK) {
			break;
		}
		n++;
	}
	return n;
}

/* What bus has received / what this node put on bus's wire. */
static uint32_t drain(uint8_t bus, hal_can_frame_t *out, uint32_t max)
{
	return take_all(hal_can_receive, bus, out, max);
}

static uint32_t wire(uint8_t bus, hal_can_frame_t *out, uint32_t max)
{
	return take_all(conf_wire_take, bus, out, max);
}

static void inject_all(uint8_t bus, const hal_can_frame_t *f, uint32_t n)
{
	uint32_t i;

	for (i = 0U; i < n; i++) {
		(void)conf_wire_inject(bus, &f[i]);
	}
	conf_let_time_pass(SETTLE_US);
}

/* This node sends n frames on bus (they then have time to reach the
 * wire); the first refusal, or SQ_OK. */
static int send_all(uint8_t bus, const hal_can_frame_t *f, uint32_t n)
{
	uint32_t i;
	int rc = SQ_OK;

	for (i = 0U; i < n; i++) {
		const int r = hal_can_send(bus, &f[i]);

		rc = (rc != SQ_OK) ? rc : r;
	}
	conf_let_time_pass(SETTLE_US);
	return rc;
}

/* The check that this node's n frames reach bus's wire intact, in order. */
static void check_sent(uint8_t bus, const hal_can_frame_t *f, uint32_t n, const char *what)
{
	hal_can_frame_t got[MAX_DRAIN];
	const int rc = send_all(bus, f, n);
	const uint32_t on_wire = wire(bus, got, MAX_DRAIN);

	report((rc == SQ_OK) && same_frames(got, on_wire, f, n), bus, what,
	       "rc %d, %u on the wire for %u sent", rc, (unsigned int)on_wire, (unsigned int)n);
}

/* ---- filters ---------------------------------------------------------------- */

typedef struct {
	const char *what;
	hal_can_filter_t filter[2];
	uint32_t count;
	hal_can_frame_t offered[4];
	uint32_t n_offered;
	uint32_t pass_mask; /* bit i: offered[i] must be received */
} filter_case_t;

static void check_filters(uint8_t bus)
{
	const filter_case_t cases[] = {
		{ "filter: standard id (11 bit, exact)",
		  { { 0x120U, HAL_CAN_STD_ID_MAX, 0U } }, 1U,
		  { frame(0x120U, 0U, 2U, 1U), frame(0x121U, 0U, 2U, 2U),
		    frame(0x120U, HAL_CAN_FLAG_EXT, 2U, 3U), frame(0x520U, 0U, 2U, 4U) }, 4U, 0x1U },
		{ "filter: extended id (29 bit, exact)",
		  { { 0x18DAF110U, HAL_CAN_EXT_ID_MAX, HAL_CAN_FLAG_EXT } }, 1U,
		  { frame(0x18DAF110U, HAL_CAN_FLAG_EXT, 8U, 5U), frame(0x18DAF111U, HAL_CAN_FLAG_EXT, 8U, 6U),
		    frame(0x110U, 0U, 8U, 7U), frame(0x08DAF110U, HAL_CAN_FLAG_EXT, 8U, 8U) }, 4U, 0x1U },
		{ "filter: masks (0x100/0x700 standard, 0x18DA0000/0x1FFF0000 extended)",
		  { { 0x100U, 0x700U, 0U }, { 0x18DA0000U, 0x1FFF0000U, HAL_CAN_FLAG_EXT } }, 2U,
		  { frame(0x1ABU, 0U, 1U, 9U), frame(0x2ABU, 0U, 1U, 10U),
		    frame(0x18DA1234U, HAL_CAN_FLAG_EXT, 1U, 11U), frame(0x18DB1234U, HAL_CAN_FLAG_EXT, 1U, 12U) },
		  4U, 0x5U },
		{ "filter: count 0 accepts no data frame",
		  { { 0U, 0U, 0U } }, 0U,
		  { frame(0x000U, 0U, 1U, 13U), frame(0x7FFU, 0U, 1U, 14U),
		    frame(0x1FFFFFFFU, HAL_CAN_FLAG_EXT, 1U, 15U) }, 3U, 0x0U },
		{ "filter: mask 0 passes every standard frame, no extended one",
		  { { 0x555U, 0U, 0U } }, 1U,
		  { frame(0x000U, 0U, 1U, 16U), frame(0x7FFU, 0U, 1U, 17U),
		    frame(0x123U, HAL_CAN_FLAG_EXT, 1U, 18U) }, 3U, 0x3U },
	};
	uint32_t c;

	for (c = 0U; c < sizeof(cases) / sizeof(cases[0]); c++) {
		const filter_case_t *k = &cases[c];
		hal_can_frame_t got[8];
		uint32_t n;
		uint32_t i;
		uint32_t j = 0U;
		bool ok = true;
		int rc;

		if (!set_up(bus, k->what)) {
			continue;
		}
		rc = hal_can_set_rx_filter(bus, k->filter, k->count);
		if (rc == SQ_ENOTSUP) {
			skip(bus, k->what, "hal_can_set_rx_filter: SQ_ENOTSUP");
			conf_backend_teardown();
			continue;
		}
		inject_all(bus, k->offered, k->n_offered);
		n = drain(bus, got, 8U);
		for (i = 0U; i < k->n_offered; i++) {
			if ((k->pass_mask & (1UL << i)) != 0U) {
				ok = ok && (j < n) && same_frame(&got[j], &k->offered[i]);
				j++;
			}
		}
		ok = ok && (rc == SQ_OK) && (n == j);
		report(ok, bus, k->what, "set rc %d, received %u of %u expected", rc, (unsigned int)n,
		       (unsigned int)j);
		conf_backend_teardown();
	}
}

static void check_filter_range(uint8_t bus)
{
	const hal_can_filter_t bad_std = { 0x800U, HAL_CAN_STD_ID_MAX, 0U };
	const hal_can_filter_t bad_ext = { 0x20000000U, HAL_CAN_EXT_ID_MAX, HAL_CAN_FLAG_EXT };
	const hal_can_filter_t bad_mask = { 0x100U, 0xFFFU, 0U };
	/* a filter's kind is EXT or not: any other flag is refused */
	const hal_can_filter_t bad_flag = { 0x100U, HAL_CAN_STD_ID_MAX, HAL_CAN_FLAG_RTR };
	int r1;
	int r2;
	int r3;
	int r4;

	if (!set_up(bus, "filter: ids and masks out of range refused")) {
		return;
	}
	r1 = hal_can_set_rx_filter(bus, &bad_std, 1U);
	r2 = hal_can_set_rx_filter(bus, &bad_ext, 1U);
	r3 = hal_can_set_rx_filter(bus, &bad_mask, 1U);
	r4 = hal_can_set_rx_filter(bus, &bad_flag, 1U);
	if ((r1 == SQ_ENOTSUP) && (r2 == SQ_ENOTSUP)) {
		skip(bus, "filter: ids and masks out of range refused", "SQ_ENOTSUP");
	} else {
		report((r1 == SQ_EINVAL) && (r2 == SQ_EINVAL) && (r3 == SQ_EINVAL), bus,
		       "filter: ids and masks out of range refused (SQ_EINVAL)", "%d %d %d", r1, r2, r3);
		report(r4 == SQ_EINVAL, bus, "filter: a flag other than EXT refused (SQ_EINVAL)", "%d",
		       r4);
	}
	conf_backend_teardown();
}

/* ---- receiving ----------------------------------------------------------------- */

static void check_receive_order_and_time(uint8_t bus)
{
	hal_can_frame_t sent[12];
	hal_can_frame_t got[16];
	uint64_t t0;
	uint64_t t1;
	uint32_t n;
	uint32_t i;
	bool order = true;
	bool mono = true;

	if (!set_up(bus, "receive order")) {
		return;
	}
	t0 = hal_time_us();
	for (i = 0U; i < 12U; i++) {
		sent[i] = frame(0x200U + (i % 3U), ((i % 4U) == 3U) ? HAL_CAN_FLAG_EXT : 0U,
				(uint8_t)(i % 9U), (uint8_t)i);
		(void)conf_wire_inject(bus, &sent[i]);
		conf_let_time_pass(1000U); /* the frames arrive at different times */
	}
	conf_let_time_pass(SETTLE_US);
	n = drain(bus, got, 16U);
	t1 = hal_time_us();
	for (i = 0U; (i < n) && (i < 12U); i++) {
		order = order && same_frame(&got[i], &sent[i]);
		mono = mono && (got[i].timestamp_us >= t0) && (got[i].timestamp_us <= t1) &&
		       ((i == 0U) || (got[i].timestamp_us >= got[i - 1U].timestamp_us));
	}
	report(order && (n == 12U), bus, "receive order: every frame once, in wire order, data intact",
	       "received %u of 12", (unsigned int)n);
	report(mono && (n == 12U), bus, "timestamps monotonic, on hal_time_us()'s clock",
	       "t0 %llu t1 %llu", (unsigned long long)t0, (unsigned long long)t1);
	conf_backend_teardown();
}

static void check_error_frame(uint8_t bus)
{
	const char *what = "error frame reported (HAL_CAN_FLAG_ERR, status.error_frames + 1)";
	const hal_can_filter_t none = { 0U, HAL_CAN_STD_ID_MAX, 0U };
	hal_can_status_t st0;
	hal_can_status_t st1;
	hal_can_frame_t got[4];
	uint32_t n;
	int rc;

	if (!set_up(bus, what)) {
		return;
	}
	/* error frames are never filtered: a filter that passes nothing else */
	(void)hal_can_set_rx_filter(bus, &none, 0U);
	(void)hal_can_get_status(bus, &st0);
	rc = conf_force_error_frame(bus);
	if (rc == SQ_ENOTSUP) {
		skip(bus, what, "the harness cannot make an error frame");
		conf_backend_teardown();
		return;
	}
	conf_let_time_pass(SETTLE_US);
	n = drain(bus, got, 4U);
	(void)hal_can_get_status(bus, &st1);
	report((rc == SQ_OK) && (n == 1U) && ((got[0].flags & HAL_CAN_FLAG_ERR) != 0U) &&
		       (st1.error_frames == st0.error_frames + 1U),
	       bus, what, "rc %d, %u frames, error_frames %u -> %u", rc, (unsigned int)n,
	       (unsigned int)st0.error_frames, (unsigned int)st1.error_frames);
	conf_backend_teardown();
}

/* ---- sending --------------------------------------------------------------------- */

static void check_send(uint8_t bus)
{
	const hal_can_frame_t f[3] = { frame(0x321U, 0U, 4U, 0xDEU), frame(0x1ABCDEF0U, HAL_CAN_FLAG_EXT, 8U, 0x11U),
				       frame(0x7FFU, 0U, 0U, 0U) };
	hal_can_frame_t bad = frame(0x800U, 0U, 1U, 0U);
	int rc;

	if (!set_up(bus, "send")) {
		return;
	}
	check_sent(bus, f, 3U, "send: standard and extended frames reach the wire in order");
	rc = hal_can_send(bus, &bad);
	bad = frame(0x100U, 0U, 1U, 0U);
	bad.dlc = 9U;
	report((rc == SQ_EINVAL) && (hal_can_send(bus, &bad) == SQ_EINVAL), bus,
	       "send: id 0x800 (standard) and DLC 9 refused (SQ_EINVAL)", "rc %d", rc);
	conf_backend_teardown();
}

/*
 * One frame rule for every backend (hal_can_common.h): a bad frame is
 * SQ_EINVAL before the backend looks at its bus, nothing reaches the wire
 * and no counter moves; the same in listen-only mode (a bad frame is not a
 * listen-only refusal).
 */
typedef struct {
	const char *what;
	hal_can_frame_t f;
} bad_frame_t;

static void check_frame_validity(uint8_t bus)
{
	const bad_frame_t cases[] = {
		{ "an undefined flag bit (0x40)", frame(0x100U, 0x40U, 1U, 1U) },
		{ "the top flag bit (0x80) on an extended frame",
		  frame(0x100U, (uint8_t)(HAL_CAN_FLAG_EXT | 0x80U), 1U, 2U) },
		{ "an error frame (HAL_CAN_FLAG_ERR)", frame(0x08U, HAL_CAN_FLAG_ERR, 8U, 3U) },
		{ "DLC 9", frame(0x100U, 0U, 9U, 4U) },
		{ "DLC 15 (remote frame)", frame(0x100U, HAL_CAN_FLAG_RTR, 15U, 5U) },
		{ "standard id 0x800", frame(0x800U, 0U, 1U, 6U) },
		{ "extended id 0x20000000", frame(0x20000000U, HAL_CAN_FLAG_EXT, 1U, 7U) },
		{ "12 bytes without FDF", frame(0x100U, 0U, 12U, 8U) },
		{ "FD length 9 (no DLC code's)", frame(0x100U, HAL_CAN_FLAG_FDF, 9U, 9U) },
		{ "FD length 13 (no DLC code's)", frame(0x100U, HAL_CAN_FLAG_FDF, 13U, 10U) },
		{ "FD length 63 (no DLC code's)", frame(0x100U, HAL_CAN_FLAG_FDF, 63U, 11U) },
		{ "FD length 65 (above 64)", frame(0x100U, HAL_CAN_FLAG_FDF, 65U, 12U) },
		{ "FDF with RTR", frame(0x100U, (uint8_t)(HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_RTR), 8U, 13U) },
		{ "BRS without FDF", frame(0x100U, HAL_CAN_FLAG_BRS, 8U, 14U) },
		{ "ESI without FDF", frame(0x100U, HAL_CAN_FLAG_ESI, 8U, 15U) },
		{ "FD standard id 0x800", frame(0x800U, HAL_CAN_FLAG_FDF, 12U, 16U) },
	};
	uint32_t c;
	uint32_t m;

	for (m = 0U; m < 2U; m++) {
		const bool lo = (m == 1U);

		for (c = 0U; c < sizeof(cases) / sizeof(cases[0]); c++) {
			char what[128];
			hal_can_status_t st0;
			hal_can_status_t st1;
			hal_can_frame_t got[4];
			uint32_t on_wire;
			int rc_mode = SQ_OK;
			int rc;

			(void)snprintf(what, sizeof(what), "send%s: %s refused (SQ_EINVAL), nothing sent",
				       lo ? " in listen-only" : "", cases[c].what);
			if (!set_up(bus, what)) {
				continue;
			}
			if (lo) {
				rc_mode = hal_can_set_mode(bus, HAL_CAN_MODE_LISTEN_ONLY);
				if (rc_mode == SQ_ENOTSUP) {
					skip(bus, what, "hal_can_set_mode: SQ_ENOTSUP");
					conf_backend_teardown();
					continue;
				}
			}
			(void)hal_can_get_status(bus, &st0);
			rc = hal_can_send(bus, &cases[c].f);
			conf_let_time_pass(SETTLE_US);
			on_wire = wire(bus, got, 4U);
			(void)hal_can_get_status(bus, &st1);
			report((rc_mode == SQ_OK) && (rc == SQ_EINVAL) && (on_wire == 0U) &&
				       (st1.tx_refused_listen_only == st0.tx_refused_listen_only) &&
				       (st1.tx_dropped == st0.tx_dropped),
			       bus, what, "rc %d, %u on the wire, refused %u -> %u", rc, (unsigned int)on_wire,
			       (unsigned int)st0.tx_refused_listen_only,
			       (unsigned int)st1.tx_refused_listen_only);
			conf_backend_teardown();
		}
	}
}

static void check_tx_full(uint8_t bus)
{
	const char *what = "TX queue full: SQ_ENOBUFS, then recovery";
	const hal_can_frame_t f = frame(0x300U, 0U, 8U, 0x5AU);
	hal_can_frame_t got[MAX_DRAIN];
	uint32_t i;
	uint32_t accepted = 0U;
	int rc = SQ_OK;

	if (!set_up(bus, what)) {
		return;
	}
	if (conf_block_tx(bus, true) == SQ_ENOTSUP) {
		skip(bus, what, "the harness cannot stop the TX path from draining");
		conf_backend_teardown();
		return;
	}
	for (i = 0U; i < MAX_FILL; i++) {
		rc = hal_can_send(bus, &f);
		if (rc != SQ_OK) {
			break;
		}
		accepted++;
	}
	report(rc == SQ_ENOBUFS, bus, "TX blocked: the queue fills and hal_can_send says SQ_ENOBUFS",
	       "last rc %d after %u accepted", rc, (unsigned int)accepted);
	(void)conf_block_tx(bus, false);
	conf_let_time_pass(SETTLE_US);
	(void)wire(bus, got, MAX_DRAIN); /* what was queued leaves */
	rc = hal_can_send(bus, &f);
	conf_let_time_pass(SETTLE_US);
	report((rc == SQ_OK) && (wire(bus, got, MAX_DRAIN) >= 1U), bus,
	       "TX unblocked: sending works again", "rc %d", rc);
	conf_backend_teardown();
}

/* Another node makes bus go bus-off (on) or lets it recover, and time
 * passes for the backend to learn it (it may from an error frame: the
 * receive queue is read). Returns what the harness said (SQ_ENOTSUP: it
 * cannot). */
static int bus_off_settle(uint8_t bus, bool on)
{
	hal_can_frame_t got[4];
	const int rc = conf_force_bus_off(bus, on);

	conf_let_time_pass(SETTLE_US);
	(void)drain(bus, got, 4U);
	return rc;
}

static void check_bus_off(uint8_t bus)
{
	const char *what = "bus-off reported (state, count, SQ_ENETUNREACH) and left";
	const hal_can_frame_t f = frame(0x301U, 0U, 1U, 1U);
	hal_can_status_t st0;
	hal_can_status_t st1;
	hal_can_status_t st2;
	int rc_off;
	int rc_on;

	if (!set_up(bus, what)) {
		return;
	}
	(void)hal_can_get_status(bus, &st0);
	if (bus_off_settle(bus, true) == SQ_ENOTSUP) {
		skip(bus, what, "the harness cannot make the controller go bus-off");
		conf_backend_teardown();
		return;
	}
	(void)hal_can_get_status(bus, &st1);
	rc_off = hal_can_send(bus, &f);
	(void)bus_off_settle(bus, false);
	(void)hal_can_get_status(bus, &st2);
	rc_on = hal_can_send(bus, &f);
	report((st1.state == HAL_CAN_STATE_BUS_OFF) && (st1.bus_off_count == st0.bus_off_count + 1U) &&
		       (rc_off == SQ_ENETUNREACH) && (st2.state != HAL_CAN_STATE_BUS_OFF) &&
		       (rc_on == SQ_OK),
	       bus, what, "state %d count %u send %d; after: state %d send %d", (int)st1.state,
	       (unsigned int)st1.bus_off_count, rc_off, (int)st2.state, rc_on);
	conf_backend_teardown();
}

/* ---- listen-only and isolation ------------------------------------------------------ */

static void check_listen_only(uint8_t bus)
{
	const hal_can_frame_t f = frame(0x302U, 0U, 2U, 2U);
	const hal_can_frame_t in = frame(0x110U, 0U, 4U, 3U);
	const uint8_t other = (uint8_t)(1U - bus);
	hal_can_status_t st0;
	hal_can_status_t st1;
	hal_can_frame_t got[4];
	uint32_t n_rx;
	int rc_mode;
	int rc;

	if (!set_up(bus, "listen-only")) {
		return;
	}
	rc_mode = hal_can_set_mode(bus, HAL_CAN_MODE_LISTEN_ONLY);
	if (rc_mode == SQ_ENOTSUP) {
		skip(bus, "listen-only sends nothing", "hal_can_set_mode: SQ_ENOTSUP");
		conf_backend_teardown();
		return;
	}
	(void)hal_can_get_status(bus, &st0);
	rc = hal_can_send(bus, &f);
	conf_let_time_pass(SETTLE_US);
	(void)hal_can_get_status(bus, &st1);
	report((rc_mode == SQ_OK) && (rc == SQ_EPERM) && (wire(bus, got, 4U) == 0U) &&
		       (st1.mode == HAL_CAN_MODE_LISTEN_ONLY) &&
		       (st1.tx_refused_listen_only == st0.tx_refused_listen_only + 1U),
	       bus, "listen-only: send refused (SQ_EPERM), counted, nothing on the wire",
	       "mode rc %d, send rc %d, refused %u -> %u", rc_mode, rc,
	       (unsigned int)st0.tx_refused_listen_only, (unsigned int)st1.tx_refused_listen_only);
	inject_all(bus, &in, 1U);
	n_rx = drain(bus, got, 4U);
	report((n_rx == 1U) && same_frame(&got[0], &in), bus, "listen-only: receiving goes on",
	       "%u received", (unsigned int)n_rx);
	if (conf_bus_count() > 1U) {
		rc = hal_can_send(other, &f);
		conf_let_time_pass(SETTLE_US);
		report((rc == SQ_OK) && (wire(other, got, 4U) == 1U), bus,
		       "listen-only: the other bus keeps sending", "rc %d", rc);
	}
	rc = hal_can_set_mode(bus, HAL_CAN_MODE_NORMAL);
	report((rc == SQ_OK) && (hal_can_send(bus, &f) == SQ_OK), bus, "back to NORMAL: sending works",
	       "rc %d", rc);
	conf_backend_teardown();
}

/* The mode is the firmware's: a bus-off and the recovery the bus makes
 * (on the in-memory bus: an injected status) leave listen-only on, and a
 * send is still refused with SQ_EPERM and counted. */
static void check_listen_only_kept(uint8_t bus)
{
	const char *what = "listen-only kept across bus-off and recovery: send still SQ_EPERM, counted";
	const hal_can_frame_t f = frame(0x304U, 0U, 2U, 6U);
	hal_can_status_t st0;
	hal_can_status_t st1;
	hal_can_frame_t got[4];
	uint32_t on_wire;
	int rc_mode;
	int rc;

	if (!set_up(bus, what)) {
		return;
	}
	rc_mode = hal_can_set_mode(bus, HAL_CAN_MODE_LISTEN_ONLY);
	if (rc_mode == SQ_ENOTSUP) {
		skip(bus, what, "hal_can_set_mode: SQ_ENOTSUP");
		conf_backend_teardown();
		return;
	}
	if (bus_off_settle(bus, true) == SQ_ENOTSUP) {
		skip(bus, what, "the harness cannot make the controller go bus-off");
		conf_backend_teardown();
		return;
	}
	(void)bus_off_settle(bus, false);
	(void)hal_can_get_status(bus, &st0);
	rc = hal_can_send(bus, &f);
	conf_let_time_pass(SETTLE_US);
	on_wire = wire(bus, got, 4U);
	(void)hal_can_get_status(bus, &st1);
	report((rc_mode == SQ_OK) && (st0.mode == HAL_CAN_MODE_LISTEN_ONLY) &&
		       (st0.state != HAL_CAN_STATE_BUS_OFF) && (rc == SQ_EPERM) && (on_wire == 0U) &&
		       (st1.tx_refused_listen_only == st0.tx_refused_listen_only + 1U),
	       bus, what, "mode %d state %d, send rc %d, %u on the wire, refused %u -> %u", (int)st0.mode,
	       (int)st0.state, rc, (unsigned int)on_wire, (unsigned int)st0.tx_refused_listen_only,
	       (unsigned int)st1.tx_refused_listen_only);
	conf_backend_teardown();
}

static void check_isolation(uint8_t bus)
{
	const uint8_t other = (uint8_t)(1U - bus);
	const hal_can_frame_t in = frame(0x111U, 0U, 3U, 4U);
	const hal_can_frame_t out = frame(0x303U, 0U, 3U, 5U);
	hal_can_frame_t got[4];
	uint32_t rx_here;
	uint32_t rx_other;
	uint32_t wire_here;
	uint32_t wire_other;
	int rc;

	if (!set_up(bus, "isolation")) {
		return;
	}
	inject_all(bus, &in, 1U);
	rx_other = drain(other, got, 4U);
	rx_here = drain(bus, got, 4U);
	rc = hal_can_send(bus, &out);
	conf_let_time_pass(SETTLE_US);
	wire_other = wire(other, got, 4U);
	wire_here = wire(bus, got, 4U);
	report((rx_here == 1U) && (rx_other == 0U) && (rc == SQ_OK) && (wire_here == 1U) &&
		       (wire_other == 0U),
	       bus, "no frame of this bus appears on the other (received or sent)",
	       "rx %u/%u, wire %u/%u", (unsigned int)rx_here, (unsigned int)rx_other,
	       (unsigned int)wire_here, (unsigned int)wire_other);
	conf_backend_teardown();
}

static void check_no_such_bus(uint8_t bus)
{
	const hal_can_frame_t f = frame(0x100U, 0U, 1U, 0U);
	hal_can_frame_t r;
	hal_can_status_t st;
	int rc[5];

	if (!set_up(bus, "no such bus")) {
		return;
	}
	rc[0] = hal_can_send(bus, &f);
	rc[1] = hal_can_receive(bus, &r);
	rc[2] = hal_can_get_status(bus, &st);
	rc[3] = hal_can_set_rx_filter(bus, NULL, 0U);
	rc[4] = hal_can_set_mode(bus, HAL_CAN_MODE_NORMAL);
	report((rc[0] == SQ_ENODEV) && (rc[1] == SQ_ENODEV) && (rc[2] == SQ_ENODEV) &&
		       (rc[3] == SQ_ENODEV) && (rc[4] == SQ_ENODEV),
	       bus, "a bus this backend lacks answers SQ_ENODEV everywhere", "%d %d %d %d %d", rc[0],
	       rc[1], rc[2], rc[3], rc[4]);
	conf_backend_teardown();
}

/* ---- CAN FD ------------------------------------------------------------------------ */

/* The data lengths of DLC codes 9..15 (ISO 11898-1:2015, table of the DLC):
 * written out here, not taken from hal.h's map. */
static const uint8_t fd_len_of_code[7] = { 12U, 16U, 20U, 24U, 32U, 48U, 64U };

#define FD_CASES 10U

/* Every FD length, standard and extended ids, BRS and ESI in every
 * combination, and FD frames of 0 and 8 bytes (FDF, not classic). */
static uint32_t fd_frames(hal_can_frame_t *f)
{
	static const uint8_t fd_flags[4] = { HAL_CAN_FLAG_FDF,
					     (uint8_t)(HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_BRS),
					     (uint8_t)(HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_ESI),
					     (uint8_t)(HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_BRS | HAL_CAN_FLAG_ESI) };
	uint32_t i;

	for (i = 0U; i < 7U; i++) {
		const uint8_t ext = ((i % 2U) == 1U) ? (uint8_t)HAL_CAN_FLAG_EXT : 0U;

		f[i] = frame((ext != 0U) ? 0x1ABCDE00U + i : 0x0A0U + i, (uint8_t)(fd_flags[i % 4U] | ext),
			     fd_len_of_code[i], (uint8_t)(0x30U + i));
	}
	f[7] = frame(0x7FFU, fd_flags[1], 0U, 0U);
	f[8] = frame(0x1FFFFFFFU, (uint8_t)(fd_flags[3] | HAL_CAN_FLAG_EXT), 8U, 0x77U);
	f[9] = frame(0x0A0U, fd_flags[1], 64U, 0xF0U); /* 64 bytes, last byte distinct */
	return FD_CASES;
}

/* A bus that carries FD: each frame both ways, intact, flags kept. */
static void check_fd_round_trip(uint8_t bus)
{
	hal_can_frame_t f[FD_CASES];
	hal_can_frame_t got[FD_CASES + 2U];
	const uint32_t m = fd_frames(f);
	uint32_t n;

	if (!set_up(bus, "FD round trip")) {
		return;
	}
	check_sent(bus, f, m,
		   "FD send: DLC codes 9..15 (12..64 bytes), 0 and 8 bytes, std/ext, BRS/ESI kept, in order");
	inject_all(bus, f, m);
	n = drain(bus, got, FD_CASES + 2U);
	report(same_frames(got, n, f, m), bus,
	       "FD receive: DLC codes 9..15 (12..64 bytes), 0 and 8 bytes, std/ext, BRS/ESI kept, in order",
	       "%u of %u received intact", (unsigned int)n, (unsigned int)m);
	conf_backend_teardown();
}

/* Classic and FD frames on one bus: one order, each keeps its format. */
static void check_fd_mixed(uint8_t bus)
{
	const hal_can_frame_t f[6] = {
		frame(0x120U, 0U, 8U, 1U), frame(0x120U, HAL_CAN_FLAG_FDF, 8U, 1U),
		frame(0x121U, (uint8_t)(HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_BRS), 24U, 2U),
		frame(0x18DAF110U, HAL_CAN_FLAG_EXT, 3U, 3U), frame(0x122U, HAL_CAN_FLAG_RTR, 4U, 0U),
		frame(0x18DAF111U, (uint8_t)(HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_EXT), 64U, 4U),
	};
	/* a filter applies to FD frames as to classic ones: 0x122 (classic
	 * remote) and 0x120..0x121 pass, extended ones by their own filter */
	const hal_can_filter_t filt[2] = { { 0x120U, 0x7FCU, 0U },
					   { 0x18DAF110U, 0x1FFFFFFEU, HAL_CAN_FLAG_EXT } };
	hal_can_frame_t got[8];
	uint32_t n;
	int rc;

	if (!set_up(bus, "classic and FD on one bus")) {
		return;
	}
	check_sent(bus, f, 6U, "classic and FD frames sent on one bus: in order, each in its format");
	rc = hal_can_set_rx_filter(bus, filt, 2U);
	inject_all(bus, f, 6U);
	n = drain(bus, got, 8U);
	report(((rc == SQ_OK) || (rc == SQ_ENOTSUP)) && same_frames(got, n, f, 6U), bus,
	       "classic and FD frames received on one bus (through filters): in order, each in its format",
	       "filter rc %d, %u of 6", rc, (unsigned int)n);
	conf_backend_teardown();
}

/* A bus that carries classic frames only: an FD frame (of any length) is
 * refused with SQ_ENOTSUP, counted, nothing sent; classic frames go on;
 * a malformed FD frame is still SQ_EINVAL (the frame rule first). */
static void check_fd_refused(uint8_t bus)
{
	const char *what = "classic-only bus: FD frames refused (SQ_ENOTSUP), counted, nothing sent";
	const hal_can_frame_t fd[3] = { frame(0x0A0U, HAL_CAN_FLAG_FDF, 24U, 1U),
					frame(0x0A1U, (uint8_t)(HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_BRS), 8U, 2U),
					frame(0x1ABCDEF0U, (uint8_t)(HAL_CAN_FLAG_FDF | HAL_CAN_FLAG_EXT), 64U, 3U) };
	const hal_can_frame_t classic = frame(0x0A2U, 0U, 8U, 4U);
	hal_can_frame_t bad = frame(0x0A0U, HAL_CAN_FLAG_FDF, 13U, 5U);
	hal_can_status_t st0;
	hal_can_status_t st1;
	hal_can_frame_t got[4];
	uint32_t on_wire;
	uint32_t i;
	int rc_bad;
	int rc_classic;
	bool refused = true;

	if (!set_up(bus, what)) {
		return;
	}
	(void)hal_can_get_status(bus, &st0);
	for (i = 0U; i < 3U; i++) {
		refused = refused && (hal_can_send(bus, &fd[i]) == SQ_ENOTSUP);
	}
	rc_bad = hal_can_send(bus, &bad);
	conf_let_time_pass(SETTLE_US);
	on_wire = wire(bus, got, 4U);
	(void)hal_can_get_status(bus, &st1);
	report(refused && (rc_bad == SQ_EINVAL) && (on_wire == 0U) &&
		       (st1.fd_unsupported == st0.fd_unsupported + 3U) &&
		       (st1.tx_dropped == st0.tx_dropped),
	       bus, what, "bad %d, %u on the wire, fd_unsupported %u -> %u", rc_bad, (unsigned int)on_wire,
	       (unsigned int)st0.fd_unsupported, (unsigned int)st1.fd_unsupported);
	rc_classic = hal_can_send(bus, &classic);
	conf_let_time_pass(SETTLE_US);
	on_wire = wire(bus, got, 4U);
	report((rc_classic == SQ_OK) && (on_wire == 1U) && same_frame(&got[0], &classic), bus,
	       "classic-only bus: classic frames still sent after FD refusals", "rc %d, %u on the wire",
	       rc_classic, (unsigned int)on_wire);
	conf_backend_teardown();
}

static void check_fd(uint8_t bus)
{
	bool fd;

	if (!set_up(bus, "CAN FD")) {
		return;
	}
	fd = conf_bus_fd(bus);
	conf_backend_teardown();
	if (fd) {
		check_fd_round_trip(bus);
		check_fd_mixed(bus);
	} else {
		check_fd_refused(bus);
		skip(bus, "FD send/receive: DLC codes 9..15, BRS/ESI kept", "this bus carries classic frames only");
		skip(bus, "classic and FD frames on one bus", "this bus carries classic frames only");
	}
}

static void check_contracts(void)
{
	const hal_can_frame_t f = frame(0x100U, 0U, 1U, 0U);
	hal_can_filter_t many[HAL_CAN_MAX_FILTERS + 1U];
	hal_can_frame_t r;
	volatile uint32_t caught = 0U; /* kept across the handler's longjmp */

	if (!set_up(0U, "contracts")) {
		return;
	}
	memset(many, 0, sizeof(many));
	caught += CONF_EXPECT_CONTRACT(hal_can_send(HAL_CAN_BUSES, &f)) ? 1U : 0U;
	caught += CONF_EXPECT_CONTRACT(hal_can_receive(0xFFU, &r)) ? 1U : 0U;
	caught += CONF_EXPECT_CONTRACT(hal_can_send(0U, NULL)) ? 1U : 0U;
	caught += CONF_EXPECT_CONTRACT(hal_can_receive(0U, NULL)) ? 1U : 0U;
	caught += CONF_EXPECT_CONTRACT(hal_can_get_status(0U, NULL)) ? 1U : 0U;
	caught += CONF_EXPECT_CONTRACT(hal_can_set_rx_filter(0U, many, HAL_CAN_MAX_FILTERS + 1U)) ? 1U : 0U;
	report(caught == 6U, 0U, "bad bus index, NULL, too many filters: the contract handler",
	       "%u of 6 caught", (unsigned int)caught);
	conf_backend_teardown();
}

int main(void)
{
	const uint32_t buses = conf_bus_count();
	uint8_t bus;

	printf("# HAL conformance suite on backend %s: %u bus(es)\n", conf_backend_name(),
	       (unsigned int)buses);
	for (bus = 0U; bus < buses; bus++) {
		check_filters(bus);
		check_filter_range(bus);
		check_receive_order_and_time(bus);
		check_error_frame(bus);
		check_send(bus);
		check_frame_validity(bus);
		check_tx_full(bus);
		check_bus_off(bus);
		check_listen_only(bus);
		check_listen_only_kept(bus);
		check_fd(bus);
		if (buses > 1U) {
			check_isolation(bus);
		}
	}
	for (bus = (uint8_t)buses; bus < HAL_CAN_BUSES; bus++) {
		check_no_such_bus(bus);
	}
	check_contracts();
	printf("RESULT: %u passed, %u failed, %u skipped\n", (unsigned int)n_pass, (unsigned int)n_fail,
	       (unsigned int)n_skip);
	return (n_fail == 0U) ? 0 : 1;
}
