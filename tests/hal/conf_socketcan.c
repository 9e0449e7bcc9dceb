/* SPDX-License-Identifier: MIT */
/*
 * conf_socketcan.c: the conformance harness of hal/linux on real SocketCAN:
 * bus 0 on $SQ_VCAN (default vcan0), bus 1 on $SQ_VCAN1 when set (the QEMU
 * guest of tests/vcan/guest.sh --vcan1 creates both). The other node on
 * each bus is a second CAN_RAW socket on the same interface: what it sends
 * reaches the HAL's socket, what the HAL sends reaches it. vcan has no
 * controller, so error frames and bus-off are the kernel's error frames
 * sent from that socket (as a controller driver would deliver them). Its TX
 * path never stalls by itself: with $SQ_TC (the path of tc; root, in the
 * guest) a blocked TX path is a token-bucket qdisc that lets almost nothing
 * out (the kernel then refuses with ENOBUFS), removed to unblock; without
 * it that check is a SKIP. The peer takes CAN FD frames too; whether a
 * bus carries them is the interface's MTU (72: FD, 16: classic only),
 * asked here with SIOCGIFMTU, not taken from the backend.
 */
#include <errno.h>
#include <stdio.h>
#include <net/if.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>

#include "conformance_backend.h"
#include "hal_linux.h"

static int peer[HAL_CAN_BUSES] = { -1, -1 };

static const char *iface_of(uint8_t bus)
{
	const char *name = getenv((bus == 0U) ? "SQ_VCAN" : "SQ_VCAN1");

	if ((bus == 0U) && ((name == NULL) || (name[0] == '\0'))) {
		return "vcan0";
	}
	return ((name != NULL) && (name[0] != '\0')) ? name : NULL;
}

const char *conf_backend_name(void)
{
	return "socketcan";
}

uint32_t conf_bus_count(void)
{
	return (iface_of(1U) != NULL) ? 2U : 1U;
}

static int peer_socket(const char *ifname)
{
	struct sockaddr_can addr;
	int fd = socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);

	if (fd < 0) {
		return -1;
	}
	memset(&addr, 0, sizeof(addr));
	addr.can_family = AF_CAN;
	addr.can_ifindex = (int)if_nametoindex(ifname);
	/* FD frames too (refused by the kernel only when sent on an MTU-16
	 * interface) */
	if ((addr.can_ifindex == 0) || (setsockopt(fd, SOL_CAN_RAW, CAN_RAW_FD_FRAMES, &(int){ 1 },
						   (socklen_t)sizeof(int)) != 0) ||
	    (bind(fd, (const struct sockaddr *)&addr, sizeof(addr)) != 0)) {
		(void)close(fd);
		return -1;
	}
	return fd;
}

void conf_backend_teardown(void)
{
	uint8_t b;

	hal_linux_close();
	for (b = 0U; b < HAL_CAN_BUSES; b++) {
		if (peer[b] >= 0) {
			(void)close(peer[b]);
		}
		peer[b] = -1;
	}
}

int conf_backend_setup(void)
{
	uint8_t b;

	conf_backend_teardown();
	for (b = 0U; b < conf_bus_count(); b++) {
		if ((hal_linux_open(b, iface_of(b), NULL) != SQ_OK) ||
		    (hal_can_set_mode(b, HAL_CAN_MODE_NORMAL) != SQ_OK) ||
		    (hal_linux_can_accept_all(b) != SQ_OK)) {
			return SQ_EIO;
		}
		peer[b] = peer_socket(iface_of(b));
		if (peer[b] < 0) {
			return SQ_EIO;
		}
	}
	return SQ_OK;
}

bool conf_bus_fd(uint8_t bus)
{
	struct ifreq ifr;
	const char *name = iface_of(bus);

	if ((bus >= HAL_CAN_BUSES) || (peer[bus] < 0) || (name == NULL) ||
	    (strlen(name) >= sizeof(ifr.ifr_name))) {
		return false;
	}
	memset(&ifr, 0, sizeof(ifr));
	memcpy(ifr.ifr_name, name, strlen(name) + 1U);
	return (ioctl(peer[bus], SIOCGIFMTU, &ifr) == 0) && (ifr.ifr_mtu >= (int)CANFD_MTU);
}

/* A classic frame goes as CAN_MTU bytes, an FD one as CANFD_MTU. */
static int peer_send(uint8_t bus, const struct canfd_frame *cf, size_t size)
{
	if ((bus >= HAL_CAN_BUSES) || (peer[bus] < 0)) {
		return SQ_ENODEV;
	}
	return (send(peer[bus], cf, size, 0) == (ssize_t)size) ? SQ_OK : SQ_EIO;
}

int conf_wire_inject(uint8_t bus, const hal_can_frame_t *frame)
{
	struct canfd_frame cf;
	size_t size = CAN_MTU;

	memset(&cf, 0, sizeof(cf));
	cf.can_id = frame->id;
	if ((frame->flags & HAL_CAN_FLAG_EXT) != 0U) {
		cf.can_id |= CAN_EFF_FLAG;
	}
	if ((frame->flags & HAL_CAN_FLAG_RTR) != 0U) {
		cf.can_id |= CAN_RTR_FLAG;
	}
	if ((frame->flags & HAL_CAN_FLAG_FDF) != 0U) {
		size = CANFD_MTU;
		cf.flags = (uint8_t)((((frame->flags & HAL_CAN_FLAG_BRS) != 0U) ? CANFD_BRS : 0U) |
				     (((frame->flags & HAL_CAN_FLAG_ESI) != 0U) ? CANFD_ESI : 0U));
	}
	cf.len = frame->dlc;
	memcpy(cf.data, frame->data, frame->dlc);
	return peer_send(bus, &cf, size);
}

int conf_wire_take(uint8_t bus, hal_can_frame_t *frame)
{
	struct canfd_frame cf;
	ssize_t n;

	if ((bus >= HAL_CAN_BUSES) || (peer[bus] < 0)) {
		return SQ_EAGAIN;
	}
	n = recv(peer[bus], &cf, sizeof(cf), MSG_DONTWAIT);
	if ((n != (ssize_t)CAN_MTU) && (n != (ssize_t)CANFD_MTU)) {
		return SQ_EAGAIN;
	}
	memset(frame, 0, sizeof(*frame));
	if ((cf.can_id & CAN_EFF_FLAG) != 0U) {
		frame->id = cf.can_id & CAN_EFF_MASK;
		frame->flags = HAL_CAN_FLAG_EXT;
	} else {
		frame->id = cf.can_id & CAN_SFF_MASK;
	}
	if ((cf.can_id & CAN_RTR_FLAG) != 0U) {
		frame->flags |= HAL_CAN_FLAG_RTR;
	}
	if (n == (ssize_t)CANFD_MTU) {
		frame->flags |= HAL_CAN_FLAG_FDF;
		frame->flags |= ((cf.flags & CANFD_BRS) != 0U) ? HAL_CAN_FLAG_BRS : 0U;
		frame->flags |= ((cf.flags & CANFD_ESI) != 0U) ? HAL_CAN_FLAG_ESI : 0U;
	}
	frame->dlc = cf.len;
	memcpy(frame->data, cf.data, (cf.len <= sizeof(frame->data)) ? cf.len : sizeof(frame->data));
	return SQ_OK;
}

static int inject_error(uint8_t bus, uint32_t cls)
{
	struct canfd_frame cf;

	memset(&cf, 0, sizeof(cf));
	cf.can_id = CAN_ERR_FLAG | cls;
	cf.len = CAN_ERR_DLC;
	return peer_send(bus, &cf, CAN_MTU);
}

int conf_force_error_frame(uint8_t bus)
{
	return inject_error(bus, CAN_ERR_PROT);
}

int conf_force_bus_off(uint8_t bus, bool on)
{
	return inject_error(bus, on ? CAN_ERR_BUSOFF : CAN_ERR_RESTARTED);
}

int conf_block_tx(uint8_t bus, bool blocked)
{
	const char *tc = getenv("SQ_TC");
	char cmd[256];
	int n;

	if ((tc == NULL) || (tc[0] == '\0') || (bus >= conf_bus_count())) {
		return SQ_ENOTSUP;
	}
	/* 1 kbit/s and a 64-byte queue: four frames wait, one leaves every
	 * 128 ms, so a burst of sends finds the queue full */
	n = snprintf(cmd, sizeof(cmd),
		     blocked ? "%s qdisc add dev %s root tbf rate 1kbit burst 200 limit 64"
			     : "%s qdisc del dev %s root",
		     tc, iface_of(bus));
	if ((n <= 0) || ((size_t)n >= sizeof(cmd))) {
		return SQ_EINVAL;
	}
	return (system(cmd) == 0) ? SQ_OK : SQ_EIO;
}

void conf_let_time_pass(uint32_t us)
{
	struct timespec ts = { .tv_sec = (time_t)(us / 1000000U),
			       .tv_nsec = (long)((us % 1000000U) * 1000U) };

	while ((nanosleep(&ts, &ts) != 0) && (errno == EINTR)) {
	}
}
