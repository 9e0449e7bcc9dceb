/* SPDX-License-Identifier: MIT */
/*
 * E2E protection compatible with AUTOSAR E2E Profile 1, variant 1A:
 *   byte 0           CRC-8 (crc8_p01: poly 0x1D, start 0x00, no final XOR)
 *                    over data ID low byte, data ID high byte, then the
 *                    frame's bytes 1 .. len-1 (the data ID is never sent);
 *   byte 1 bits 0..3 alive counter 0..14, +1 (mod 15) per sent frame;
 *                    15 is never sent.
 *
 * Receiver (e2e_p01_check), P01 semantics:
 *   - every call first lets the tolerated counter jump grow by one (up to
 *     14), so a receiver that calls check once per expected cycle, also when
 *     nothing arrived (data == NULL -> NONEWDATA), tolerates the frames lost
 *     while it waited;
 *   - wrong length or CRC                      -> WRONGCRC
 *   - first good frame after init/reset        -> INITIAL (adopts its counter)
 *   - counter 15 (cannot be sent by a P01 sender) -> WRONGSEQUENCE
 *   - delta 0                                  -> REPEATED
 *   - delta 1                                  -> OK
 *   - 2 <= delta <= tolerated jump             -> OKSOMELOST, lost = delta-1
 *   - delta beyond the tolerated jump          -> WRONGSEQUENCE, and the
 *     receiver adopts that frame's counter as its new reference (resync);
 *   - the next frame that continues the adopted sequence (delta within the
 *     tolerated jump)                          -> INITIAL (usable)
 *   So a sender that restarted its counter costs one frame, and a single
 *   stray frame also costs the good frame after it; plain R4.0 P01 (no
 *   resync) would instead reject every frame after a counter jump until
 *   the counters wrap (up to 15 frames). This is P01's later SyncCounter
 *   scheme with SyncCounterInit = 1, reported as INITIAL.
 *   The reference counter otherwise changes only on INITIAL, OK and
 *   OKSOMELOST. e2e_p01_rx_reset() forces a full restart (the next good
 *   frame, whatever its counter, is INITIAL).
 *
 * A frame's content may be used ONLY when e2e_p01_status_usable() is true
 * (OK, OKSOMELOST, INITIAL). Every other status means "discard this frame".
 * Status values are contiguous for counting; AUTOSAR's numeric codes differ.
 */
#ifndef E2E_P01_H
#define E2E_P01_H

#include <stdbool.h>
#include <stdint.h>

#define E2E_P01_COUNTER_MAX      14U /* counters run 0..14                  */
#define E2E_P01_COUNTER_INVALID  15U
#define E2E_P01_MIN_LEN           2U /* CRC byte + counter byte            */
#define E2E_P01_MAX_LEN           8U /* classic CAN                        */

typedef enum {
	E2E_P01_STATUS_OK = 0,        /* next expected counter                 */
	E2E_P01_STATUS_INITIAL,       /* first good frame after init/resync    */
	E2E_P01_STATUS_OKSOMELOST,    /* accepted; rx->lost_data frames lost   */
	E2E_P01_STATUS_REPEATED,      /* same counter again: discard           */
	E2E_P01_STATUS_WRONGSEQUENCE, /* jump too large or counter 15: discard */
	E2E_P01_STATUS_WRONGCRC,      /* CRC or length wrong: discard          */
	E2E_P01_STATUS_NONEWDATA,     /* check called without a frame          */
	E2E_P01_STATUS_COUNT
} e2e_p01_status_t;

/* Static configuration of one protected message. */
typedef struct {
	uint16_t data_id;          /* 16-bit data ID, both bytes in the CRC    */
	uint8_t data_len;          /* frame length in bytes, 2..8 (the DLC)    */
	uint8_t max_delta_counter; /* MaxDeltaCounterInit, 1..14               */
} e2e_p01_config_t;

/* Sender state: the counter the next protect writes (0..14). */
typedef struct {
	uint8_t counter;
} e2e_p01_tx_t;

/* Receiver state of one message. Read the fields, never write them. */
typedef struct {
	uint8_t last_valid_counter;
	uint8_t max_delta_counter;   /* currently tolerated jump            */
	uint8_t lost_data;           /* frames lost, set on OKSOMELOST       */
	bool wait_for_first_data;
	bool resync;                 /* reference adopted from a WRONGSEQUENCE */
	e2e_p01_status_t status;     /* result of the last check             */
	uint32_t status_count[E2E_P01_STATUS_COUNT]; /* saturating, per status */
} e2e_p01_rx_t;

/*
 * Check a configuration: SQ_OK, or SQ_EINVAL if cfg is NULL, data_len is
 * outside 2..8 or max_delta_counter outside 1..14.
 */
int e2e_p01_config_check(const e2e_p01_config_t *cfg);

/* Sender: start counting at 0. */
void e2e_p01_tx_init(e2e_p01_tx_t *tx);

/*
 * Protect a packed frame in place: write tx->counter into the low nibble of
 * data[1] (high nibble kept), the CRC into data[0], then advance the
 * counter (14 -> 0). len must equal cfg->data_len.
 * Returns SQ_OK. A NULL pointer, a bad config, a len mismatch or a counter
 * > 14 in tx is a programming error: hal_contract_failed() (hal.h).
 */
int e2e_p01_protect(const e2e_p01_config_t *cfg, e2e_p01_tx_t *tx,
		    uint8_t *data, uint8_t len);

/* The CRC protect would write, for a frame whose bytes 1..len-1 are final.
 * Returns SQ_OK and *crc; NULL, a bad config or a len mismatch is a
 * programming error (hal_contract_failed). */
int e2e_p01_crc(const e2e_p01_config_t *cfg, const uint8_t *data,
		uint8_t len, uint8_t *crc);

/* Receiver: zero the counts and wait for the first frame. */
void e2e_p01_rx_init(e2e_p01_rx_t *rx);

/* Receiver: forget the sequence (next good frame is INITIAL), keep the
 * counts. For a monitor that declared the input lost and starts over. */
void e2e_p01_rx_reset(e2e_p01_rx_t *rx);

/*
 * Check one received frame (or data == NULL: no frame this cycle) and
 * update rx (state, status, status_count). Returns the status. An invalid
 * cfg or a NULL rx is a programming error (hal_contract_failed, hal.h),
 * never reported as a wrong CRC; a bad frame is WRONGCRC.
 */
e2e_p01_status_t e2e_p01_check(const e2e_p01_config_t *cfg,
			       e2e_p01_rx_t *rx,
			       const uint8_t *data, uint8_t len);

/*
 * The receiver's sequence machine above, for any counter that runs
 * 0 .. modulus - 1 (2..256), shared by E2E P02 (16), P05 (256) and the
 * counter-only check (input_rx). e2e_rx_cycle: one receive cycle (the tolerated jump grows up
 * to modulus - 1). e2e_rx_sequence: the status of a frame whose CRC (if
 * any) is good. e2e_rx_record: store and count a status; returns it.
 */
void e2e_rx_cycle(e2e_p01_rx_t *rx, uint16_t modulus);
e2e_p01_status_t e2e_rx_sequence(e2e_p01_rx_t *rx, uint8_t counter,
				 uint16_t modulus, uint8_t max_delta_counter);
e2e_p01_status_t e2e_rx_record(e2e_p01_rx_t *rx, e2e_p01_status_t st);
/* One whole receive cycle of a profile whose every counter value is valid
 * (P02, P05): the cycle, then NONEWDATA (no frame), WRONGCRC (!crc_ok: CRC
 * or length wrong) or the sequence status of counter; recorded, returned. */
e2e_p01_status_t e2e_rx_frame(e2e_p01_rx_t *rx, uint16_t modulus, bool present, bool crc_ok,
			      uint8_t counter, uint8_t max_delta_counter);

/* True exactly for OK, OKSOMELOST and INITIAL: the frame may be used. */
bool e2e_p01_status_usable(e2e_p01_status_t status);

/* "OK", "INITIAL", "OKSOMELOST", "REPEATED", "WRONGSEQUENCE", "WRONGCRC",
 * "NONEWDATA"; "?" otherwise. */
const char *e2e_p01_status_name(e2e_p01_status_t status);

#endif /* E2E_P01_H */
