/* SPDX-License-Identifier: MIT */
/*
 * hal_linux_can.c: hal.h's CAN functions on SocketCAN: one CAN_RAW socket
 * per bus (bus 0 .. HAL_CAN_BUSES-1, each opened on its own interface by
 * hal_linux_open()), each with everything below. A bus in listen-only mode
 * refuses every send (SQ_EPERM, counted in tx_refused_listen_only); the
 * interface itself is made listen-only by its administrator.
 *
 * - CAN FD follows the interface: at MTU 72 (CANFD_MTU, asked with
 *   SIOCGIFMTU at open) the socket takes FD frames (CAN_RAW_FD_FRAMES): a
 *   read of CANFD_MTU bytes is an FD frame (HAL_CAN_FLAG_FDF, and BRS/ESI
 *   from canfd_frame.flags), one of CAN_MTU bytes a classic one, and an FDF
 *   frame is sent as a struct canfd_frame. At MTU 16 FD stays off, said
 *   once per interface on stderr, and an FD send is refused (SQ_ENOTSUP,
 *   counted in fd_unsupported).
 * - Filters are the kernel's (CAN_RAW_FILTER): unwanted frames never reach
 *   the process. Filters set before hal_linux_open() are kept and applied.
 * - Error frames (CAN_RAW_ERR_FILTER) update hal_can_status_t (every state
 *   change through hal_can_state_change(), which counts it) and are also
 *   handed to the firmware as HAL_CAN_FLAG_ERR frames (id = error class,
 *   data = the kernel's 8 bytes) so it can count and report them:
 *     CAN_ERR_BUSOFF      state BUS_OFF, bus_off_count + 1 (on entry)
 *     CAN_ERR_CRTL        data[1]: warning/passive/active sets the state,
 *                         RX overflow counts into rx_overruns, TX overflow
 *                         into tx_dropped
 *     CAN_ERR_RESTARTED   state ERROR_ACTIVE (controller restarted)
 *     CAN_ERR_CNT         data[6] = TEC, data[7] = REC
 *   A data frame received while BUS_OFF also means the controller is back
 *   on the bus (a bus-off node receives nothing), so a lost RESTARTED frame
 *   cannot leave the state stuck.
 * - Receive times are the kernel's SO_TIMESTAMP (CLOCK_REALTIME at the
 *   socket layer), moved to the hal_time_us() base by
 *   hal_linux_realtime_to_mono_us() and clamped to [previous stamp, now].
 * - SO_RXQ_OVFL: each frame carries the socket's cumulative drop count; the
 *   difference to the previous frame's count goes into rx_overruns.
 * - Send never blocks for long: on ENOBUFS (queueing discipline full) or
 *   EAGAIN (socket send buffer full) it waits with back-off (EAGAIN: poll
 *   for POLLOUT; ENOBUFS: sleep, as POLLOUT does not see a full qdisc) and
 *   retries, at most tx_max_tries attempts within tx_budget_us (default 3
 *   within 1 ms), then counts the frame in tx_dropped and returns
 *   SQ_ENOBUFS. Waits after attempt k are budget >> (tries - k): 250 us and
 *   500 us by default.
 */
#include <errno.h>
#include <fcntl.h>
#include <net/if.h>
#include <net/if_arp.h>
#include <poll.h>
#include <stdio.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>

#include "hal_can_common.h"
#include "hal_linux.h"

#ifndef CAN_ERR_CNT
#define CAN_ERR_CNT 0x00000200U
#endif

_Static_assert(HAL_CAN_MAX_DLEN >= CANFD_MAX_DLEN, "a host build's frames hold an FD frame's data");

#define DEFAULT_TX_TRIES 3U
#define DEFAULT_TX_BUDGET_US 1000U
/* Frames the HAL cannot hand over (CAN XL, a malformed length) are skipped;
 * bound the skipping per call. */
#define MAX_SKIP_PER_RECEIVE 16

/* Every error class but lost arbitration (normal on a busy bus). */
#define ERR_MASK (CAN_ERR_TX_TIMEOUT | CAN_ERR_CRTL | CAN_ERR_PROT | CAN_ERR_TRX \
		  | CAN_ERR_ACK | CAN_ERR_BUSOFF | CAN_ERR_BUSERROR | CAN_ERR_RESTARTED \
		  | CAN_ERR_CNT)

typedef struct {
	int fd;
	bool named;                    /* an interface was given: the bus exists */
	bool fd_on;                    /* the interface's MTU carries CAN FD     */
	char ifname[IFNAMSIZ];
	char fd_off_said[IFNAMSIZ];    /* "FD off" was said for this interface   */
	uint32_t tx_max_tries;
	uint32_t tx_budget_us;
	hal_can_status_t status;       /* its mode the firmware's: kept over re-opens */
	hal_linux_can_stats_t stats;
	uint32_t last_drop_count;
	uint64_t last_stamp_us;
	/* Filter set by hal_can_set_rx_filter(), applied again on open. */
	bool filter_set;
	uint32_t filter_count;
	struct can_filter filters[HAL_CAN_MAX_FILTERS];
} lc_t;

#define LC_CLOSED { .fd = -1, .status = { .state = HAL_CAN_STATE_STOPPED } }
_Static_assert(HAL_CAN_BUSES == 2U, "one initialiser per bus");
static lc_t can[HAL_CAN_BUSES] = { LC_CLOSED, LC_CLOSED };

/* The bus, or NULL for a valid index that has no interface: bus 0 always
 * exists (stopped until opened), another bus once hal_linux_open() named
 * an interface for it. */
static lc_t *linux_can_bus_of(uint8_t bus)
{
	HAL_REQUIRE(bus < HAL_CAN_BUSES);
	return ((bus == 0U) || can[bus].named) ? &can[bus] : NULL;
}

int hal_linux_can_fd(uint8_t bus)
{
	HAL_REQUIRE(bus < HAL_CAN_BUSES);
	return can[bus].fd;
}

bool hal_linux_can_fd_on(uint8_t bus)
{
	HAL_REQUIRE(bus < HAL_CAN_BUSES);
	return can[bus].fd_on;
}

static void close_bus(lc_t *c)
{
	if (c->fd >= 0) {
		(void)close(c->fd);
	}
	c->fd = -1;
	c->fd_on = false;
	(void)hal_can_state_change(&c->status, HAL_CAN_STATE_STOPPED);
}

void hal_linux_close(void)
{
	uint32_t b;

	for (b = 0U; b < HAL_CAN_BUSES; b++) {
		close_bus(&can[b]);
	}
}

static int apply_filter(lc_t *c)
{
	static const struct can_filter all = { .can_id = 0U, .can_mask = 0U };
	const void *opt = &all;
	socklen_t len = (socklen_t)sizeof(all);

	if (c->fd < 0) {
		return SQ_OK;
	}
	if (c->filter_set) {
		opt = c->filter_count > 0U ? c->filters : NULL;
		len = (socklen_t)(c->filter_count * sizeof(c->filters[0]));
	}
	if (setsockopt(c->fd, SOL_CAN_RAW, CAN_RAW_FILTER, opt, len) != 0) {
		hal_linux_set_error("%s: CAN_RAW_FILTER: %s", c->ifname, strerror(errno));
		return SQ_EINVAL;
	}
	return SQ_OK;
}

int hal_can_set_rx_filter(uint8_t bus, const hal_can_filter_t *filters, uint32_t count)
{
	lc_t *c = linux_can_bus_of(bus);
	const int rc = hal_can_filter_check(filters, count);
	uint32_t i;

	if (rc != SQ_OK) {
		return rc;
	}
	if (c == NULL) {
		return SQ_ENODEV;
	}
	for (i = 0; i < count; i++) {
		const bool ext = (filters[i].flags & HAL_CAN_FLAG_EXT) != 0U;

		/* The kind (EFF flag) always matches exactly; RTR is not masked. */
		c->filters[i].can_id = filters[i].id | (ext ? CAN_EFF_FLAG : 0U);
		c->filters[i].can_mask = filters[i].mask | CAN_EFF_FLAG;
	}
	c->filter_count = count;
	c->filter_set = true;
	return apply_filter(c);
}

int hal_linux_can_accept_all(uint8_t bus)
{
	lc_t *c = linux_can_bus_of(bus);

	if (c == NULL) {
		return SQ_ENODEV;
	}
	c->filter_set = false;
	c->filter_count = 0U;
	return apply_filter(c);
}

static int open_fail(int fd, int code)
{
	(void)close(fd);
	hal_linux_add_fault(HAL_FAULT_CAN_INIT);
	return code;
}

static int set_int_opt(const lc_t *c, int fd, int level, int name, int value, const char *what)
{
	if (setsockopt(fd, level, name, &value, (socklen_t)sizeof(value)) != 0) {
		hal_linux_set_error("%s: setsockopt %s: %s", c->ifname, what, strerror(errno));
		return -1;
	}
	return 0;
}

/* CAN FD as the interface's MTU says: on at CANFD_MTU (or more: a CAN XL
 * interface carries FD frames too), off at CAN_MTU, said once per
 * interface. 0, or -1 (error set) when the socket refuses FD frames. */
static int set_fd_mode(lc_t *c, int fd, struct ifreq *ifr)
{
	c->fd_on = false;
	if (ioctl(fd, SIOCGIFMTU, ifr) != 0) {
		hal_linux_set_error("%s: SIOCGIFMTU: %s", c->ifname, strerror(errno));
		return -1;
	}
	if (ifr->ifr_mtu >= (int)CANFD_MTU) {
		if (set_int_opt(c, fd, SOL_CAN_RAW, CAN_RAW_FD_FRAMES, 1, "CAN_RAW_FD_FRAMES") != 0) {
			return -1;
		}
		c->fd_on = true;
	} else if (strcmp(c->fd_off_said, c->ifname) != 0) {
		(void)fprintf(stderr, "%s: MTU %d, CAN FD off (ip link set %s mtu %u)\n", c->ifname,
			      ifr->ifr_mtu, c->ifname, (unsigned int)CANFD_MTU);
		memcpy(c->fd_off_said, c->ifname, sizeof(c->fd_off_said));
	}
	return 0;
}

int hal_linux_open(uint8_t bus, const char *ifname, const hal_linux_can_opts_t *opts)
{
	static const hal_linux_can_opts_t defaults = { 0 };
	const can_err_mask_t err_mask = ERR_MASK;
	hal_can_mode_t mode;
	struct sockaddr_can addr;
	struct ifreq ifr;
	size_t len;
	int fd;
	lc_t *c;

	HAL_REQUIRE(bus < HAL_CAN_BUSES);
	c = &can[bus];
	close_bus(c);
	if (opts == NULL) {
		opts = &defaults;
	}
	if (ifname == NULL || (len = strlen(ifname)) == 0U || len >= IFNAMSIZ) {
		hal_linux_set_error("bad CAN interface name (1 to %d characters)", IFNAMSIZ - 1);
		return SQ_EINVAL;
	}
	memcpy(c->ifname, ifname, len + 1U);
	c->named = true;

	fd = socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
	if (fd < 0) {
		int err = errno;

		hal_linux_add_fault(HAL_FAULT_CAN_INIT);
		if (err == EAFNOSUPPORT || err == EPROTONOSUPPORT) {
			hal_linux_set_error("%s: this kernel has no CAN support (socket(PF_CAN, CAN_RAW): %s): "
					    "modprobe can-raw / vcan (or use a kernel with CONFIG_CAN)",
					    ifname, strerror(err));
			return SQ_ENOTSUP;
		}
		if (err == EACCES || err == EPERM) {
			hal_linux_set_error("%s: permission denied opening a CAN socket (%s)", ifname,
					    strerror(err));
			return SQ_EIO;
		}
		hal_linux_set_error("%s: socket(PF_CAN, CAN_RAW): %s", ifname, strerror(err));
		return SQ_EIO;
	}

	memset(&ifr, 0, sizeof(ifr));
	memcpy(ifr.ifr_name, ifname, len + 1U);
	if (ioctl(fd, SIOCGIFINDEX, &ifr) != 0) {
		int err = errno;

		if (err == ENODEV) {
			hal_linux_set_error("%s: no such network interface (for a virtual bus: "
					    "sudo ip link add dev %s type vcan && sudo ip link set up %s)",
					    ifname, ifname, ifname);
			return open_fail(fd, SQ_ENOENT);
		}
		hal_linux_set_error("%s: SIOCGIFINDEX: %s", ifname, strerror(err));
		return open_fail(fd, SQ_EIO);
	}
	memset(&addr, 0, sizeof(addr));
	addr.can_family = AF_CAN;
	addr.can_ifindex = ifr.ifr_ifindex;

	if (ioctl(fd, SIOCGIFHWADDR, &ifr) != 0) {
		hal_linux_set_error("%s: SIOCGIFHWADDR: %s", ifname, strerror(errno));
		return open_fail(fd, SQ_EIO);
	}
	if (ifr.ifr_hwaddr.sa_family != ARPHRD_CAN) {
		hal_linux_set_error("%s: not a CAN interface (link type %u, CAN is %u)", ifname,
				    (unsigned int)ifr.ifr_hwaddr.sa_family, (unsigned int)ARPHRD_CAN);
		return open_fail(fd, SQ_EINVAL);
	}
	if (ioctl(fd, SIOCGIFFLAGS, &ifr) != 0) {
		hal_linux_set_error("%s: SIOCGIFFLAGS: %s", ifname, strerror(errno));
		return open_fail(fd, SQ_EIO);
	}
	if ((ifr.ifr_flags & IFF_UP) == 0) {
		hal_linux_set_error("%s: interface is down (bring it up: sudo ip link set up %s; "
				    "a real adapter also needs its bitrate: ... type can bitrate 500000)",
				    ifname, ifname);
		return open_fail(fd, SQ_ENETDOWN);
	}

	if (setsockopt(fd, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &err_mask,
		       (socklen_t)sizeof(err_mask)) != 0) {
		hal_linux_set_error("%s: CAN_RAW_ERR_FILTER: %s", ifname, strerror(errno));
		return open_fail(fd, SQ_EIO);
	}
	if (set_fd_mode(c, fd, &ifr) != 0
	    || set_int_opt(c, fd, SOL_SOCKET, SO_TIMESTAMP, 1, "SO_TIMESTAMP") != 0
	    || set_int_opt(c, fd, SOL_SOCKET, SO_RXQ_OVFL, 1, "SO_RXQ_OVFL") != 0
	    || (opts->rcvbuf_bytes > 0
		&& set_int_opt(c, fd, SOL_SOCKET, SO_RCVBUF, opts->rcvbuf_bytes, "SO_RCVBUF") != 0)
	    || (opts->sndbuf_bytes > 0
		&& set_int_opt(c, fd, SOL_SOCKET, SO_SNDBUF, opts->sndbuf_bytes, "SO_SNDBUF") != 0)) {
		return open_fail(fd, SQ_EIO);
	}
	if (bind(fd, (const struct sockaddr *)&addr, (socklen_t)sizeof(addr)) != 0) {
		int err = errno;

		hal_linux_set_error("%s: bind: %s", ifname, strerror(err));
		return open_fail(fd, err == ENODEV ? SQ_ENOENT : SQ_EIO);
	}

	c->fd = fd;
	c->tx_max_tries = opts->tx_max_tries > 0U ? opts->tx_max_tries : DEFAULT_TX_TRIES;
	if (c->tx_max_tries > 16U) {
		c->tx_max_tries = 16U;
	}
	c->tx_budget_us = opts->tx_budget_us > 0U ? opts->tx_budget_us : DEFAULT_TX_BUDGET_US;
	/* a fresh start: every counter zero, the controller on the bus, the
	 * firmware's mode kept */
	mode = c->status.mode;
	memset(&c->status, 0, sizeof(c->status));
	c->status.mode = mode;
	memset(&c->stats, 0, sizeof(c->stats));
	c->status.state = HAL_CAN_STATE_ERROR_ACTIVE;
	c->last_drop_count = 0U;
	c->last_stamp_us = 0U;
	if (apply_filter(c) != SQ_OK) {
		close_bus(c);
		return SQ_EIO;
	}
	hal_linux_set_error("%s", "");
	return SQ_OK;
}

/* Listen-only is the HAL's promise not to send: the interface itself is
 * set listen-only by its administrator (ip link set can0 type can
 * listen-only on), which this process cannot do without a capability. */
int hal_can_set_mode(uint8_t bus, hal_can_mode_t mode)
{
	lc_t *c = linux_can_bus_of(bus);

	HAL_REQUIRE((mode == HAL_CAN_MODE_NORMAL) || (mode == HAL_CAN_MODE_LISTEN_ONLY));
	if (c == NULL) {
		return SQ_ENODEV;
	}
	c->status.mode = mode;
	return SQ_OK;
}

int hal_can_set_bitrate(uint8_t bus, uint32_t bitrate_kbps)
{
	if (linux_can_bus_of(bus) == NULL) {
		return SQ_ENODEV;
	}
	/* the interface's bit rate is set by its administrator (ip link) */
	(void)bitrate_kbps;
	return SQ_ENOTSUP;
}

int hal_can_get_status(uint8_t bus, hal_can_status_t *status)
{
	const lc_t *c = linux_can_bus_of(bus);

	HAL_REQUIRE(status != NULL);
	if (c == NULL) {
		return SQ_ENODEV;
	}
	*status = c->status;
	if (c->fd < 0) {
		status->state = HAL_CAN_STATE_STOPPED;
	}
	return SQ_OK;
}

void hal_linux_can_get_stats(uint8_t bus, hal_linux_can_stats_t *stats)
{
	HAL_REQUIRE((bus < HAL_CAN_BUSES) && (stats != NULL));
	*stats = can[bus].stats;
}

static void count_error_frame(lc_t *c, const struct can_frame *cf)
{
	canid_t cls = cf->can_id & CAN_ERR_MASK;

	c->status.error_frames++;
	if ((cls & CAN_ERR_BUSOFF) != 0U) {
		(void)hal_can_state_change(&c->status, HAL_CAN_STATE_BUS_OFF);
	}
	if ((cls & CAN_ERR_CRTL) != 0U) {
		uint8_t d1 = cf->data[1];

		if ((d1 & CAN_ERR_CRTL_RX_OVERFLOW) != 0U) {
			c->status.rx_overruns++;
			c->stats.rx_ctrl_overflows++;
		}
		if ((d1 & CAN_ERR_CRTL_TX_OVERFLOW) != 0U) {
			c->status.tx_dropped++;
		}
		if ((d1 & (CAN_ERR_CRTL_RX_PASSIVE | CAN_ERR_CRTL_TX_PASSIVE)) != 0U) {
			(void)hal_can_state_change(&c->status, HAL_CAN_STATE_ERROR_PASSIVE);
		} else if ((d1 & (CAN_ERR_CRTL_RX_WARNING | CAN_ERR_CRTL_TX_WARNING)) != 0U) {
			(void)hal_can_state_change(&c->status, HAL_CAN_STATE_ERROR_WARNING);
		} else if ((d1 & CAN_ERR_CRTL_ACTIVE) != 0U) {
			(void)hal_can_state_change(&c->status, HAL_CAN_STATE_ERROR_ACTIVE);
		}
	}
	if ((cls & CAN_ERR_RESTARTED) != 0U) {
		(void)hal_can_state_change(&c->status, HAL_CAN_STATE_ERROR_ACTIVE);
	}
	if ((cls & CAN_ERR_CNT) != 0U) {
		c->status.tx_error_count = cf->data[6];
		c->status.rx_error_count = cf->data[7];
	}
}

/* The kernel's receive time on our clock, or now when there is none. */
static uint64_t frame_stamp_us(lc_t *c, const struct msghdr *msg)
{
	const struct cmsghdr *cm;
	uint64_t now_us = hal_time_us();
	uint64_t stamp_us = now_us;
	bool found = false;

	for (cm = CMSG_FIRSTHDR(msg); cm != NULL; cm = CMSG_NXTHDR((struct msghdr *)msg, (struct cmsghdr *)cm)) {
		size_t payload;

		if (cm->cmsg_level != SOL_SOCKET) {
			continue;
		}
		payload = cm->cmsg_len - CMSG_LEN(0);
		if (cm->cmsg_type == SO_RXQ_OVFL && payload >= sizeof(uint32_t)) {
			uint32_t drops;

			memcpy(&drops, CMSG_DATA(cm), sizeof(drops));
			/* Cumulative, wraps: the unsigned difference is right. */
			c->status.rx_overruns += drops - c->last_drop_count;
			c->stats.rx_kernel_drops += (uint32_t)(drops - c->last_drop_count);
			c->last_drop_count = drops;
		} else if (cm->cmsg_type == SCM_TIMESTAMP) {
			/* struct timeval: two 64-bit fields (64-bit ABIs and
			 * SO_TIMESTAMP_NEW) or two 32-bit ones (old 32-bit). */
			if (payload >= 2U * sizeof(int64_t)) {
				int64_t tv[2];

				memcpy(tv, CMSG_DATA(cm), sizeof(tv));
				stamp_us = hal_linux_realtime_to_mono_us(tv[0], tv[1] * 1000);
				found = true;
			} else if (payload >= 2U * sizeof(int32_t)) {
				int32_t tv[2];

				memcpy(tv, CMSG_DATA(cm), sizeof(tv));
				stamp_us = hal_linux_realtime_to_mono_us(tv[0], (int64_t)tv[1] * 1000);
				found = true;
			}
		}
	}
	if (!found) {
		c->stats.ts_fallbacks++;
	}
	if (stamp_us > now_us) {
		stamp_us = now_us;
	}
	if (stamp_us < c->last_stamp_us) {
		stamp_us = c->last_stamp_us;
	}
	c->last_stamp_us = stamp_us;
	return stamp_us;
}

/* The HAL_CAN_FLAG_* of a frame the kernel gave: an error frame is ERR
 * alone; an FD frame (read as CANFD_MTU bytes) is FDF with its BRS/ESI. */
static uint8_t hal_flags_of(canid_t can_id, bool fd, uint8_t fd_flags)
{
	uint8_t flags = 0U;

	if ((can_id & CAN_ERR_FLAG) != 0U) {
		return fd ? (uint8_t)(HAL_CAN_FLAG_ERR | HAL_CAN_FLAG_FDF) : (uint8_t)HAL_CAN_FLAG_ERR;
	}
	if ((can_id & CAN_EFF_FLAG) != 0U) {
		flags |= HAL_CAN_FLAG_EXT;
	}
	if ((can_id & CAN_RTR_FLAG) != 0U) {
		flags |= HAL_CAN_FLAG_RTR;
	}
	if (fd) {
		flags |= HAL_CAN_FLAG_FDF;
		flags |= ((fd_flags & CANFD_BRS) != 0U) ? HAL_CAN_FLAG_BRS : 0U;
		flags |= ((fd_flags & CANFD_ESI) != 0U) ? HAL_CAN_FLAG_ESI : 0U;
	}
	return flags;
}

int hal_can_receive(uint8_t bus, hal_can_frame_t *frame)
{
	lc_t *c = linux_can_bus_of(bus);
	int skipped;

	HAL_REQUIRE(frame != NULL);
	if (c == NULL) {
		return SQ_ENODEV;
	}
	if (c->fd < 0) {
		return SQ_ENETDOWN;
	}
	for (skipped = 0; skipped < MAX_SKIP_PER_RECEIVE; skipped++) {
		union {
			struct can_frame cf;
			struct canfd_frame fd;
		} buf;
		union {
			struct cmsghdr align;
			char space[CMSG_SPACE(4U * sizeof(int64_t)) + CMSG_SPACE(sizeof(uint32_t)) + 64U];
		} ctrl;
		struct iovec iov = { .iov_base = &buf, .iov_len = sizeof(buf) };
		struct msghdr msg;
		uint8_t flags;
		ssize_t n;

		memset(&msg, 0, sizeof(msg));
		msg.msg_iov = &iov;
		msg.msg_iovlen = 1;
		msg.msg_control = &ctrl;
		msg.msg_controllen = sizeof(ctrl);
		n = recvmsg(c->fd, &msg, MSG_DONTWAIT);
		if (n < 0) {
			int err = errno;

			if (err == EAGAIN || err == EWOULDBLOCK || err == EINTR) {
				return SQ_EAGAIN;
			}
			(void)hal_can_state_change(&c->status, HAL_CAN_STATE_STOPPED);
			hal_linux_set_error("%s: receive: %s", c->ifname, strerror(err));
			return SQ_ENETDOWN;
		}
		if (((size_t)n != CAN_MTU && (size_t)n != CANFD_MTU) || (msg.msg_flags & MSG_TRUNC) != 0) {
			c->stats.rx_skipped++; /* CAN XL, or cut short */
			continue;
		}
		flags = hal_flags_of(buf.fd.can_id, (size_t)n == CANFD_MTU, buf.fd.flags);
		if (!hal_can_format_ok(flags, buf.fd.len)) {
			c->stats.rx_skipped++; /* a length no frame of its format has */
			continue;
		}
		memset(frame, 0, sizeof(*frame));
		frame->timestamp_us = frame_stamp_us(c, &msg);
		frame->flags = flags;
		frame->dlc = buf.fd.len;
		if ((flags & HAL_CAN_FLAG_ERR) != 0U) {
			count_error_frame(c, &buf.cf);
			frame->id = buf.cf.can_id & CAN_ERR_MASK;
			memcpy(frame->data, buf.cf.data, frame->dlc);
			c->stats.rx_err_frames++;
			return SQ_OK;
		}
		if (c->status.state == HAL_CAN_STATE_BUS_OFF
		    || c->status.state == HAL_CAN_STATE_STOPPED) {
			/* Receiving again: the controller is back on the bus. */
			(void)hal_can_state_change(&c->status, HAL_CAN_STATE_ERROR_ACTIVE);
		}
		frame->id = buf.fd.can_id & (((flags & HAL_CAN_FLAG_EXT) != 0U) ? CAN_EFF_MASK : CAN_SFF_MASK);
		if ((flags & HAL_CAN_FLAG_RTR) == 0U) {
			memcpy(frame->data, buf.fd.data, frame->dlc);
		}
		c->stats.rx_frames++;
		return SQ_OK;
	}
	return SQ_EAGAIN;
}

/* Wait up to wait_us: for POLLOUT after EAGAIN, plainly after ENOBUFS. */
static void tx_backoff(const lc_t *c, bool wait_for_pollout, uint32_t wait_us)
{
	struct timespec ts = {
		.tv_sec = (time_t)(wait_us / 1000000U),
		.tv_nsec = (long)((wait_us % 1000000U) * 1000U),
	};

	if (wait_for_pollout) {
		struct pollfd pfd = { .fd = c->fd, .events = POLLOUT, .revents = 0 };

		(void)ppoll(&pfd, 1, &ts, NULL);
	} else {
		/* An early wake by a signal only shortens the back-off. */
		(void)nanosleep(&ts, NULL);
	}
}

static void note_tx_time(lc_t *c, uint64_t start_us)
{
	uint64_t took_us = hal_time_us() - start_us;

	if (took_us > c->stats.tx_worst_us) {
		c->stats.tx_worst_us = took_us > UINT32_MAX ? UINT32_MAX : (uint32_t)took_us;
	}
}

int hal_can_send(uint8_t bus, const hal_can_frame_t *frame)
{
	lc_t *c = linux_can_bus_of(bus);
	/* a closed socket knows no MTU: stopped, whatever the format */
	const int rc = hal_can_send_admit(frame, (c != NULL) ? &c->status : NULL,
					  (c != NULL) && (c->fd_on || (c->fd < 0)));
	struct canfd_frame cf;
	size_t size = CAN_MTU;
	uint64_t start_us;
	uint32_t attempt;

	if (rc != SQ_OK) {
		return rc;
	}
	if (c->fd < 0) {
		return SQ_ENETDOWN;
	}
	if (c->status.state == HAL_CAN_STATE_BUS_OFF) {
		return SQ_ENETUNREACH;
	}
	/* struct can_frame is struct canfd_frame's first CAN_MTU bytes */
	memset(&cf, 0, sizeof(cf));
	cf.can_id = frame->id;
	if ((frame->flags & HAL_CAN_FLAG_EXT) != 0U) {
		cf.can_id |= CAN_EFF_FLAG;
	}
	cf.len = frame->dlc;
	if ((frame->flags & HAL_CAN_FLAG_FDF) != 0U) {
		size = CANFD_MTU;
		/* the size makes it FD (the kernel sets CANFD_FDF itself) */
		cf.flags = (uint8_t)((((frame->flags & HAL_CAN_FLAG_BRS) != 0U) ? CANFD_BRS : 0U) |
				     (((frame->flags & HAL_CAN_FLAG_ESI) != 0U) ? CANFD_ESI : 0U));
	}
	if ((frame->flags & HAL_CAN_FLAG_RTR) != 0U) {
		cf.can_id |= CAN_RTR_FLAG;
	} else {
		memcpy(cf.data, frame->data, frame->dlc);
	}

	start_us = hal_time_us();
	for (attempt = 1U;; attempt++) {
		ssize_t n = send(c->fd, &cf, size, MSG_DONTWAIT);
		uint64_t elapsed_us;
		uint32_t wait_us;
		int err;

		if (n == (ssize_t)size) {
			c->stats.tx_frames++;
			note_tx_time(c, start_us);
			return SQ_OK;
		}
		err = n < 0 ? errno : EIO;
		if (err == ENETDOWN || err == ENODEV || err == ENXIO) {
			(void)hal_can_state_change(&c->status, HAL_CAN_STATE_STOPPED);
			hal_linux_set_error("%s: send: %s", c->ifname, strerror(err));
			return SQ_ENETDOWN;
		}
		if (err == EINVAL) {
			return SQ_EINVAL;
		}
		if (err != ENOBUFS && err != EAGAIN && err != EWOULDBLOCK && err != EINTR) {
			/* Anything else is lost too: counted, never silent. */
			c->status.tx_dropped++;
			c->stats.tx_dropped++;
			hal_linux_set_error("%s: send: %s", c->ifname, strerror(err));
			note_tx_time(c, start_us);
			return SQ_ENETDOWN;
		}
		if (err == ENOBUFS) {
			c->stats.tx_enobufs++;
		} else if (err != EINTR) {
			c->stats.tx_eagain++;
		}
		elapsed_us = hal_time_us() - start_us;
		if (attempt >= c->tx_max_tries || elapsed_us >= c->tx_budget_us) {
			c->status.tx_dropped++;
			c->stats.tx_dropped++;
			note_tx_time(c, start_us);
			return SQ_ENOBUFS;
		}
		wait_us = c->tx_budget_us >> (c->tx_max_tries - attempt);
		if (wait_us > c->tx_budget_us - elapsed_us) {
			wait_us = (uint32_t)(c->tx_budget_us - elapsed_us);
		}
		c->stats.tx_retries++;
		tx_backoff(c, err != ENOBUFS, wait_us);
	}
}
