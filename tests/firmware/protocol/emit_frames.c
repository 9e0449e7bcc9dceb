/* SPDX-License-Identifier: MIT */
/*
 * Test helper for the DBC cross-checks (tests/protocol/ Python checks).
 *
 *   emit_frames          pack + E2E-protect a set of frames of every message
 *                        with hand-chosen raw values through the firmware's
 *                        own msg_*_pack() and e2e_p01_protect(); print each as
 *                        a candump -L line followed by a line
 *                        "# <id> <Signal>=<raw>:<physical> ..." giving the
 *                        INTENDED physical values, written by hand here
 *                        ("NA" = the signal's not-available value).
 *   emit_frames --table  print the C side of the interface description:
 *                        MSG/SIG lines from msg_table/msg_sig_table and DEF
 *                        lines for the value-table defines.
 */
#include <inttypes.h>
#include <stdio.h>
#include <string.h>

#include "any_msg.h"
#include "e2e_p01.h"
#include "sq_status.h"
#include "squeal_msgs.h"

#define MAX_FIELDS 16

struct field {
	const char *name;
	int32_t raw;
	const char *phys; /* intended physical value, "NA" = not available */
};

struct frame_case {
	uint16_t id;
	struct field f[MAX_FIELDS];
};

/* Physical values are written from the DBC's scaling by hand, not computed. */
static const struct frame_case cases[] = {
	{ MSG_DISC_SPEED_ID, { { "DiscSpeed_radps", 12345, "123.45" } } },
	{ MSG_DISC_SPEED_ID, { { "DiscSpeed_radps", 0, "0" } } },
	{ MSG_DISC_SPEED_ID, { { "DiscSpeed_radps", 1, "0.01" } } },
	{ MSG_DISC_SPEED_ID, { { "DiscSpeed_radps", 25000, "250" } } },
	{ MSG_DISC_SPEED_ID, { { "DiscSpeed_radps", 65534, "655.34" } } },
	{ MSG_DISC_SPEED_ID, { { "DiscSpeed_radps", 65535, "NA" } } },
	{ MSG_PAD_FORCE_ID, { { "PadForce_N", 18000, "9000" } } },
	{ MSG_PAD_FORCE_ID, { { "PadForce_N", 1, "0.5" } } },
	{ MSG_PAD_FORCE_ID, { { "PadForce_N", 0, "0" } } },
	{ MSG_PAD_FORCE_ID, { { "PadForce_N", 65534, "32767" } } },
	{ MSG_PAD_FORCE_ID, { { "PadForce_N", 65535, "NA" } } },
	{ MSG_SQUEAL_STATUS_ID, { { "SquealState", 2, "2" }, { "WarningLevel", 3, "3" },
				  { "BasinRatio", 65535, "NA" }, { "HopfMargin_mps", -123, "-1.23" } } },
	{ MSG_SQUEAL_STATUS_ID, { { "SquealState", 0, "0" }, { "WarningLevel", 0, "0" },
				  { "BasinRatio", 10000, "1" }, { "HopfMargin_mps", 32767, "327.67" } } },
	{ MSG_SQUEAL_STATUS_ID, { { "SquealState", 1, "1" }, { "WarningLevel", 2, "2" },
				  { "BasinRatio", 1234, "0.1234" }, { "HopfMargin_mps", -32767, "-327.67" } } },
	{ MSG_SQUEAL_STATUS_ID, { { "SquealState", 15, "15" }, { "WarningLevel", 1, "1" },
				  { "BasinRatio", 0, "0" }, { "HopfMargin_mps", -32768, "NA" } } },
	{ MSG_SQUEAL_STATUS_ID, { { "SquealState", 3, "3" }, { "WarningLevel", 0, "0" },
				  { "BasinRatio", 1, "0.0001" }, { "HopfMargin_mps", -1, "-0.01" } } },
	/* BorderMargin_sigma: raw x 0.1 - 0.1; 0 = not available, 255 = 25.4 or more */
	{ MSG_SQUEAL_STATUS_ID, { { "SquealState", 1, "1" }, { "WarningLevel", 3, "3" },
				  { "BorderMargin_sigma", 21, "2" } } },
	{ MSG_SQUEAL_STATUS_ID, { { "SquealState", 0, "0" }, { "BorderMargin_sigma", 1, "0" } } },
	{ MSG_SQUEAL_STATUS_ID, { { "SquealState", 2, "2" }, { "WarningLevel", 3, "3" },
				  { "BorderMargin_sigma", 254, "25.3" } } },
	{ MSG_SQUEAL_STATUS_ID, { { "SquealState", 0, "0" }, { "BorderMargin_sigma", 255, "25.4" } } },
	{ MSG_SQUEAL_STATUS_ID, { { "SquealState", 0, "0" }, { "BorderMargin_sigma", 0, "NA" } } },
	{ MSG_SQUEAL_DETAIL_ID, { { "V0_mps", 1234, "12.34" }, { "HopfSpeed_mps", 123, "1.23" },
				  { "TriggerVelocity_mps", 50, "0.5" },
				  { "VehicleSpeedBorder_kph", 111, "11.1" } } },
	{ MSG_SQUEAL_DETAIL_ID, { { "V0_mps", 16382, "163.82" }, { "HopfSpeed_mps", 16383, "NA" },
				  { "TriggerVelocity_mps", 4094, "40.94" },
				  { "VehicleSpeedBorder_kph", 4095, "NA" } } },
	{ MSG_SQUEAL_DETAIL_ID, { { "V0_mps", 16383, "NA" }, { "HopfSpeed_mps", 16382, "163.82" },
				  { "TriggerVelocity_mps", 4095, "NA" },
				  { "VehicleSpeedBorder_kph", 4094, "409.4" } } },
	{ MSG_SQUEAL_DETAIL_ID, { { "V0_mps", 0, "0" }, { "HopfSpeed_mps", 0, "0" },
				  { "TriggerVelocity_mps", 0, "0" },
				  { "VehicleSpeedBorder_kph", 0, "0" } } },
	{ MSG_SQUEAL_DETAIL2_ID, { { "Force_N", 18000, "9000" }, { "HopfForce_N", 65534, "65534" },
				   { "LcAmplitude_um", 1234, "123.4" } } },
	{ MSG_SQUEAL_DETAIL2_ID, { { "Force_N", 65535, "NA" }, { "HopfForce_N", 65535, "NA" },
				   { "LcAmplitude_um", 65535, "NA" } } },
	{ MSG_SQUEAL_DETAIL2_ID, { { "Force_N", 1, "0.5" }, { "HopfForce_N", 1, "1" },
				   { "LcAmplitude_um", 65534, "6553.4" } } },
	{ MSG_SQUEAL_DIAG_ID, { { "SquealDiag_Page", 0, "0" }, { "Fault_SpeedStale", 1, "1" },
				{ "Fault_ForceImplausible", 1, "1" }, { "Fault_TxOverflow", 1, "1" },
				{ "Uptime_s", 0x123456, "1193046" }, { "BusOffCount", 7, "7" } } },
	{ MSG_SQUEAL_DIAG_ID, { { "SquealDiag_Page", 1, "1" }, { "Fault_ForceStale", 1, "1" },
				{ "Fault_E2eSpeed", 1, "1" }, { "Fault_E2eForce", 1, "1" },
				{ "Fault_SpeedImplausible", 1, "1" }, { "Fault_CalibInvalid", 1, "1" },
				{ "Fault_BusOffSeen", 1, "1" }, { "Fault_ClockFallback", 1, "1" },
				{ "Fault_CanInit", 1, "1" },
				{ "WorstTaskTime_us", 837, "837" }, { "RxOverrunCount", 65535, "65535" } } },
	{ MSG_SQUEAL_DIAG_ID, { { "SquealDiag_Page", 2, "2" },
				{ "E2eErrorCountSpeed", 1, "1" }, { "E2eErrorCountForce", 40000, "40000" } } },
	{ MSG_SQUEAL_DIAG_ID, { { "SquealDiag_Page", 3, "3" }, { "Fault_CalibInvalid", 1, "1" },
				{ "TxOverflowCount", 300, "300" }, { "RxBadFrameCount", 2, "2" } } },
	{ MSG_SQUEAL_DIAG_ID, { { "SquealDiag_Page", 0, "0" },
				{ "Uptime_s", 16777215, "16777215" }, { "BusOffCount", 255, "255" } } },
	{ MSG_SQUEAL_DIAG_ID, { { "SquealDiag_Page", 4, "4" }, { "Fault_SelfTest", 1, "1" },
				{ "HseFreq_MHz", 80, "8" }, { "ResetCause", 4, "4" }, { "BorLevel", 3, "3" },
				{ "LoopbackCan1", 0, "0" }, { "LoopbackCan2", 2, "2" },
				{ "StackHighWater_B", 480, "480" } } },
	{ MSG_SQUEAL_DIAG_ID, { { "SquealDiag_Page", 4, "4" }, { "HseFreq_MHz", 255, "NA" },
				{ "ResetCause", 6, "6" }, { "BorLevel", 7, "NA" }, { "LoopbackCan1", 3, "3" },
				{ "LoopbackCan2", 1, "1" }, { "StackHighWater_B", 16383, "NA" } } },
};

static const char *const fault_names[] = {
	"Fault_SpeedStale", "Fault_ForceStale", "Fault_E2eSpeed", "Fault_E2eForce",
	"Fault_SpeedImplausible", "Fault_ForceImplausible", "Fault_CalibInvalid",
	"Fault_BusOffSeen", "Fault_ClockFallback", "Fault_CanInit", "Fault_TxOverflow",
	"Fault_SelfTest",
};


#define IS(n) (strcmp(name, (n)) == 0)

/* Store raw into the struct field named like the DBC signal. */
static int set_field(uint16_t id, any_msg_t *m, const char *name, int32_t raw)
{
	switch (id) {
	case MSG_DISC_SPEED_ID:
		if (IS("DiscSpeed_radps")) { m->ds.disc_speed_radps = (uint16_t)raw; return 0; }
		break;
	case MSG_PAD_FORCE_ID:
		if (IS("PadForce_N")) { m->pf.pad_force_n = (uint16_t)raw; return 0; }
		break;
	case MSG_SQUEAL_STATUS_ID:
		if (IS("SquealState")) { m->st.squeal_state = (uint8_t)raw; return 0; }
		if (IS("WarningLevel")) { m->st.warning_level = (uint8_t)raw; return 0; }
		if (IS("BasinRatio")) { m->st.basin_ratio = (uint16_t)raw; return 0; }
		if (IS("HopfMargin_mps")) { m->st.hopf_margin_mps = (int16_t)raw; return 0; }
		if (IS("BorderMargin_sigma")) { m->st.border_margin_sigma = (uint8_t)raw; return 0; }
		break;
	case MSG_SQUEAL_DETAIL_ID:
		if (IS("V0_mps")) { m->dt.v0_mps = (uint16_t)raw; return 0; }
		if (IS("HopfSpeed_mps")) { m->dt.hopf_speed_mps = (uint16_t)raw; return 0; }
		if (IS("TriggerVelocity_mps")) { m->dt.trigger_velocity_mps = (uint16_t)raw; return 0; }
		if (IS("VehicleSpeedBorder_kph")) { m->dt.vehicle_speed_border_kph = (uint16_t)raw; return 0; }
		break;
	case MSG_SQUEAL_DETAIL2_ID:
		if (IS("Force_N")) { m->d2.force_n = (uint16_t)raw; return 0; }
		if (IS("HopfForce_N")) { m->d2.hopf_force_n = (uint16_t)raw; return 0; }
		if (IS("LcAmplitude_um")) { m->d2.lc_amplitude_um = (uint16_t)raw; return 0; }
		break;
	case MSG_SQUEAL_DIAG_ID:
		if (IS("SquealDiag_Page")) { m->dg.page = (uint8_t)raw; return 0; }
		if (IS("Uptime_s")) { m->dg.uptime_s = (uint32_t)raw; return 0; }
		if (IS("BusOffCount")) { m->dg.bus_off_count = (uint8_t)raw; return 0; }
		if (IS("WorstTaskTime_us")) { m->dg.worst_task_time_us = (uint16_t)raw; return 0; }
		if (IS("RxOverrunCount")) { m->dg.rx_overrun_count = (uint16_t)raw; return 0; }
		if (IS("E2eErrorCountSpeed")) { m->dg.e2e_error_count_speed = (uint16_t)raw; return 0; }
		if (IS("E2eErrorCountForce")) { m->dg.e2e_error_count_force = (uint16_t)raw; return 0; }
		if (IS("TxOverflowCount")) { m->dg.tx_overflow_count = (uint16_t)raw; return 0; }
		if (IS("RxBadFrameCount")) { m->dg.rx_bad_frame_count = (uint16_t)raw; return 0; }
		if (IS("HseFreq_MHz")) { m->dg.hse_freq_100khz = (uint8_t)raw; return 0; }
		if (IS("ResetCause")) { m->dg.reset_cause = (uint8_t)raw; return 0; }
		if (IS("BorLevel")) { m->dg.bor_level = (uint8_t)raw; return 0; }
		if (IS("LoopbackCan1")) { m->dg.loopback_can1 = (uint8_t)raw; return 0; }
		if (IS("LoopbackCan2")) { m->dg.loopback_can2 = (uint8_t)raw; return 0; }
		if (IS("StackHighWater_B")) { m->dg.stack_high_water_b = (uint16_t)raw; return 0; }
		for (unsigned int i = 0; i < sizeof(fault_names) / sizeof(fault_names[0]); i++) {
			if (IS(fault_names[i])) {
				if (raw != 0) {
					m->dg.fault_bits = (uint16_t)(m->dg.fault_bits | (1U << i));
				}
				return 0;
			}
		}
		break;
	default:
		break;
	}
	return -1;
}


static int emit_frames(void)
{
	e2e_p01_tx_t tx[MSG_COUNT];
	unsigned long long t_us = 0;

	for (size_t i = 0; i < MSG_COUNT; i++) {
		e2e_p01_tx_init(&tx[i]);
	}
	for (size_t c = 0; c < sizeof(cases) / sizeof(cases[0]); c++) {
		const struct frame_case *fc = &cases[c];
		const msg_desc_t *md = msg_desc_find(fc->id);
		e2e_p01_config_t cfg;
		any_msg_t m;
		uint8_t d[8];
		uint8_t dlc = 0;
		int rc;

		if (md == NULL) {
			fprintf(stderr, "case %zu: unknown id\n", c);
			return 1;
		}
		memset(&m, 0, sizeof(m));
		for (size_t k = 0; k < MAX_FIELDS && fc->f[k].name != NULL; k++) {
			if (set_field(fc->id, &m, fc->f[k].name, fc->f[k].raw) != 0) {
				fprintf(stderr, "case %zu: no field %s\n", c, fc->f[k].name);
				return 1;
			}
		}
		rc = any_msg_pack(fc->id, &m, d, &dlc);
		if (rc != SQ_OK) {
			fprintf(stderr, "case %zu: pack failed %d\n", c, rc);
			return 1;
		}
		cfg.data_id = md->data_id;
		cfg.data_len = md->dlc;
		cfg.max_delta_counter = 1;
		rc = e2e_p01_protect(&cfg, &tx[md - msg_table], d, dlc);
		if (rc != SQ_OK) {
			fprintf(stderr, "case %zu: protect failed %d\n", c, rc);
			return 1;
		}
		printf("(%010llu.%06llu) vcan0 %03X#", t_us / 1000000ULL, t_us % 1000000ULL,
		       (unsigned int)fc->id);
		for (unsigned int b = 0; b < dlc; b++) {
			printf("%02X", (unsigned int)d[b]);
		}
		printf("\n# 0x%03X", (unsigned int)fc->id);
		for (size_t k = 0; k < MAX_FIELDS && fc->f[k].name != NULL; k++) {
			printf(" %s=%" PRId32 ":%s", fc->f[k].name, fc->f[k].raw, fc->f[k].phys);
		}
		printf("\n");
		t_us += 10000ULL;
	}
	return 0;
}

static void def(const char *name, long value)
{
	printf("DEF\t%s\t%ld\n", name, value);
}

static int emit_table(void)
{
	for (size_t i = 0; i < MSG_COUNT; i++) {
		const msg_desc_t *m = &msg_table[i];

		printf("MSG\t0x%03X\t%s\t%u\t%u\t0x%04X\n", (unsigned int)m->id, m->name,
		       (unsigned int)m->dlc, (unsigned int)m->period_ms,
		       (unsigned int)m->data_id);
		for (unsigned int j = 0; j < m->sig_count; j++) {
			const msg_sig_desc_t *s = &msg_sig_table[m->sig_first + j];
			char mux[8];

			if ((s->flags & MSG_SIG_MUXOR) != 0U) {
				snprintf(mux, sizeof(mux), "M");
			} else if ((s->flags & MSG_SIG_MUXED) != 0U) {
				snprintf(mux, sizeof(mux), "m%u", (unsigned int)s->mux_value);
			} else {
				snprintf(mux, sizeof(mux), "-");
			}
			printf("SIG\t0x%03X\t%s\t[%s]\t%u\t%u\t%d\t%s\t%" PRId32 "\t%" PRId32
			       "\t%" PRId32 "\t%" PRId32 "\t%" PRId32 "\t%s\t%d\n",
			       (unsigned int)s->msg_id, s->name, s->unit,
			       (unsigned int)s->start_bit, (unsigned int)s->length,
			       (s->flags & MSG_SIG_SIGNED) != 0U, mux, s->factor_num,
			       s->factor_den, s->offset_num, s->raw_min, s->raw_max,
			       (s->flags & MSG_SIG_HAS_NA) != 0U ? "NA" : "-",
			       (int)((s->flags & MSG_SIG_HAS_NA) != 0U ? s->na_raw : 0));
		}
	}
	for (unsigned int v = 0; v < 16U; v++) { /* msg_squeal_state_name() */
		const char *n = msg_squeal_state_name((uint8_t)v);

		if (n != NULL) {
			printf("STATENAME\t%u\t%s\n", v, n);
		}
	}
	for (unsigned int v = 0; v < 256U; v++) { /* msg_squeal_state_slot() */
		printf("STATESLOT\t%u\t%u\n", v, (unsigned int)msg_squeal_state_slot(v));
	}
	def("MSG_SQUEAL_STATE_STABLE", MSG_SQUEAL_STATE_STABLE);
	def("MSG_SQUEAL_STATE_BISTABLE", MSG_SQUEAL_STATE_BISTABLE);
	def("MSG_SQUEAL_STATE_UNSTABLE", MSG_SQUEAL_STATE_UNSTABLE);
	def("MSG_SQUEAL_STATE_NOT_SLIDING", MSG_SQUEAL_STATE_NOT_SLIDING);
	def("MSG_SQUEAL_STATE_FAULT", MSG_SQUEAL_STATE_FAULT);
	def("MSG_WARNING_LEVEL_NONE", MSG_WARNING_LEVEL_NONE);
	def("MSG_WARNING_LEVEL_ADVISORY", MSG_WARNING_LEVEL_ADVISORY);
	def("MSG_WARNING_LEVEL_WARNING", MSG_WARNING_LEVEL_WARNING);
	def("MSG_WARNING_LEVEL_CRITICAL", MSG_WARNING_LEVEL_CRITICAL);
	def("MSG_DIAG_PAGE_UPTIME", MSG_DIAG_PAGE_UPTIME);
	def("MSG_DIAG_PAGE_TASK", MSG_DIAG_PAGE_TASK);
	def("MSG_DIAG_PAGE_E2E", MSG_DIAG_PAGE_E2E);
	def("MSG_DIAG_PAGE_FRAMES", MSG_DIAG_PAGE_FRAMES);
	def("MSG_DIAG_PAGE_SELFTEST", MSG_DIAG_PAGE_SELFTEST);
	def("MSG_DIAG_PAGE_COUNT", MSG_DIAG_PAGE_COUNT);
	def("MSG_FAULT_SPEED_STALE", MSG_FAULT_SPEED_STALE);
	def("MSG_FAULT_FORCE_STALE", MSG_FAULT_FORCE_STALE);
	def("MSG_FAULT_E2E_SPEED", MSG_FAULT_E2E_SPEED);
	def("MSG_FAULT_E2E_FORCE", MSG_FAULT_E2E_FORCE);
	def("MSG_FAULT_SPEED_IMPLAUSIBLE", MSG_FAULT_SPEED_IMPLAUSIBLE);
	def("MSG_FAULT_FORCE_IMPLAUSIBLE", MSG_FAULT_FORCE_IMPLAUSIBLE);
	def("MSG_FAULT_CALIB_INVALID", MSG_FAULT_CALIB_INVALID);
	def("MSG_FAULT_BUS_OFF_SEEN", MSG_FAULT_BUS_OFF_SEEN);
	def("MSG_FAULT_CLOCK_FALLBACK", MSG_FAULT_CLOCK_FALLBACK);
	def("MSG_FAULT_CAN_INIT", MSG_FAULT_CAN_INIT);
	def("MSG_FAULT_TX_OVERFLOW", MSG_FAULT_TX_OVERFLOW);
	def("MSG_FAULT_SELF_TEST", MSG_FAULT_SELF_TEST);
	def("MSG_FAULT_ALL", MSG_FAULT_ALL);
	/* the defines the monitor uses directly, per message */
	def("MSG_DISC_SPEED_ID", MSG_DISC_SPEED_ID);
	def("MSG_DISC_SPEED_DLC", MSG_DISC_SPEED_DLC);
	def("MSG_DISC_SPEED_PERIOD_MS", MSG_DISC_SPEED_PERIOD_MS);
	def("MSG_DISC_SPEED_DATA_ID", MSG_DISC_SPEED_DATA_ID);
	def("MSG_PAD_FORCE_ID", MSG_PAD_FORCE_ID);
	def("MSG_PAD_FORCE_DLC", MSG_PAD_FORCE_DLC);
	def("MSG_PAD_FORCE_PERIOD_MS", MSG_PAD_FORCE_PERIOD_MS);
	def("MSG_PAD_FORCE_DATA_ID", MSG_PAD_FORCE_DATA_ID);
	def("MSG_SQUEAL_STATUS_ID", MSG_SQUEAL_STATUS_ID);
	def("MSG_SQUEAL_STATUS_DLC", MSG_SQUEAL_STATUS_DLC);
	def("MSG_SQUEAL_STATUS_PERIOD_MS", MSG_SQUEAL_STATUS_PERIOD_MS);
	def("MSG_SQUEAL_STATUS_DATA_ID", MSG_SQUEAL_STATUS_DATA_ID);
	def("MSG_SQUEAL_DETAIL_ID", MSG_SQUEAL_DETAIL_ID);
	def("MSG_SQUEAL_DETAIL_DLC", MSG_SQUEAL_DETAIL_DLC);
	def("MSG_SQUEAL_DETAIL_PERIOD_MS", MSG_SQUEAL_DETAIL_PERIOD_MS);
	def("MSG_SQUEAL_DETAIL_DATA_ID", MSG_SQUEAL_DETAIL_DATA_ID);
	def("MSG_SQUEAL_DIAG_ID", MSG_SQUEAL_DIAG_ID);
	def("MSG_SQUEAL_DIAG_DLC", MSG_SQUEAL_DIAG_DLC);
	def("MSG_SQUEAL_DIAG_PERIOD_MS", MSG_SQUEAL_DIAG_PERIOD_MS);
	def("MSG_SQUEAL_DIAG_DATA_ID", MSG_SQUEAL_DIAG_DATA_ID);
	def("MSG_SQUEAL_DETAIL2_ID", MSG_SQUEAL_DETAIL2_ID);
	def("MSG_SQUEAL_DETAIL2_DLC", MSG_SQUEAL_DETAIL2_DLC);
	def("MSG_SQUEAL_DETAIL2_PERIOD_MS", MSG_SQUEAL_DETAIL2_PERIOD_MS);
	def("MSG_SQUEAL_DETAIL2_DATA_ID", MSG_SQUEAL_DETAIL2_DATA_ID);
	/* per-signal range defines: SIGNAL max and NA */
	def("MSG_DISC_SPEED_RADPS_MAX", MSG_DISC_SPEED_RADPS_MAX);
	def("MSG_DISC_SPEED_RADPS_NA", MSG_DISC_SPEED_RADPS_NA);
	def("MSG_PAD_FORCE_N_MAX", MSG_PAD_FORCE_N_MAX);
	def("MSG_PAD_FORCE_N_NA", MSG_PAD_FORCE_N_NA);
	def("MSG_BASIN_RATIO_MAX", MSG_BASIN_RATIO_MAX);
	def("MSG_BASIN_RATIO_NA", MSG_BASIN_RATIO_NA);
	def("MSG_HOPF_MARGIN_MPS_MIN", MSG_HOPF_MARGIN_MPS_MIN);
	def("MSG_HOPF_MARGIN_MPS_MAX", MSG_HOPF_MARGIN_MPS_MAX);
	def("MSG_HOPF_MARGIN_MPS_NA", MSG_HOPF_MARGIN_MPS_NA);
	def("MSG_V0_MPS_MAX", MSG_V0_MPS_MAX);
	def("MSG_V0_MPS_NA", MSG_V0_MPS_NA);
	def("MSG_HOPF_SPEED_MPS_MAX", MSG_HOPF_SPEED_MPS_MAX);
	def("MSG_HOPF_SPEED_MPS_NA", MSG_HOPF_SPEED_MPS_NA);
	def("MSG_TRIGGER_VELOCITY_MPS_MAX", MSG_TRIGGER_VELOCITY_MPS_MAX);
	def("MSG_TRIGGER_VELOCITY_MPS_NA", MSG_TRIGGER_VELOCITY_MPS_NA);
	def("MSG_VEHICLE_SPEED_BORDER_KPH_MAX", MSG_VEHICLE_SPEED_BORDER_KPH_MAX);
	def("MSG_VEHICLE_SPEED_BORDER_KPH_NA", MSG_VEHICLE_SPEED_BORDER_KPH_NA);
	def("MSG_FORCE_N_MAX", MSG_FORCE_N_MAX);
	def("MSG_FORCE_N_NA", MSG_FORCE_N_NA);
	def("MSG_HOPF_FORCE_N_MAX", MSG_HOPF_FORCE_N_MAX);
	def("MSG_HOPF_FORCE_N_NA", MSG_HOPF_FORCE_N_NA);
	def("MSG_LC_AMPLITUDE_UM_MAX", MSG_LC_AMPLITUDE_UM_MAX);
	def("MSG_LC_AMPLITUDE_UM_NA", MSG_LC_AMPLITUDE_UM_NA);
	def("MSG_UPTIME_S_MAX", MSG_UPTIME_S_MAX);
	def("MSG_BUS_OFF_COUNT_MAX", MSG_BUS_OFF_COUNT_MAX);
	def("MSG_DIAG_COUNT16_MAX", MSG_DIAG_COUNT16_MAX);
	return 0;
}

int main(int argc, char **argv)
{
	if (argc == 2 && strcmp(argv[1], "--table") == 0) {
		return emit_table();
	}
	if (argc == 1) {
		return emit_frames();
	}
	fprintf(stderr, "usage: %s [--table]\n", argv[0]);
	return 2;
}
