/* SPDX-License-Identifier: MIT */
/*
 * A simulated pair of bxCAN controllers (CAN1 master with the 28 filter
 * banks, CAN2 slave) with their wires, written from RM0090 section 32 and
 * independent of hal/stm32f4/bxcan.c: the driver, built with -DBXCAN_SIM,
 * reads and writes these registers as it would the chip's, and the
 * simulation behaves as the manual says (write-1-to-clear bits, mailboxes,
 * the 3-deep FIFO with overrun, BTR writable only in initialisation mode,
 * filter banks in all four mask/list x 16/32-bit layouts, CAN2SB, silent
 * and loopback mode, CAN2 working only with CAN1's clock, ACKs). Interrupt
 * handlers run when the interrupt mask and the NVIC let them: when the
 * driver unmasks, when time passes, while the driver polls a register.
 */
#ifndef BXCAN_SIM_H
#define BXCAN_SIM_H

#include <stdbool.h>
#include <stdint.h>

#include "hal.h"

#define SIM_BUSES 2U

/* Everything back to reset: registers, RCC, wires, clock, NVIC, counters;
 * and the driver's own state (bxcan_sim_driver_reset). */
void sim_reset(void);

/* Another node sends this frame on bus `bus` (the wire of controller
 * `bus`). Returns true when some controller acknowledged it (a running
 * controller in normal mode ACKs every valid frame, filter or not). */
bool sim_inject(uint8_t bus, const hal_can_frame_t *f);
/* Oldest frame that some controller put on the wire of `bus`. */
bool sim_wire_take(uint8_t bus, hal_can_frame_t *f);
uint32_t sim_wire_count(uint8_t bus);
/* Dominant bits this node drove on `bus` other than its own frames:
 * ACKs and error flags (silent mode must leave this at 0). */
uint32_t sim_dominant_count(uint8_t bus);

/* An error with last error code lec (CAN_ESR.LEC, RM0090 32.9.2: 1 stuff,
 * 2 form, 3 acknowledgment, 4 bit recessive, 5 bit dominant, 6 CRC), REC
 * + 1, the status-change interrupt pending; sim_error_frame: lec 3. */
void sim_error_code(uint8_t bus, uint32_t lec);
void sim_error_frame(uint8_t bus);
bool sim_bus_off(uint8_t bus, bool on); /* true: not bus-off */
/* The error counters as the bus left them, flags as CAN_ESR sets them
 * (RM0090 32.9.2): EWGF at TEC or REC >= 96, EPVF above 127; BOFF only by
 * sim_bus_off. The status-change interrupt pending. */
void sim_error_counters(uint8_t bus, uint8_t tec, uint8_t rec);
void sim_block_tx(uint8_t bus, bool blocked);
/* The controller ignores initialisation requests (no clock, QEMU). */
void sim_controller_dead(uint8_t bus, bool dead);

/* Set CAN_FMR.CAN2SB behind the driver's back (as a bootloader might). */
void sim_poke_can2sb(uint32_t sb);

/* Let time pass: the wires move, interrupts run. */
void sim_advance_us(uint32_t us);
uint64_t sim_now_us(void);

/* Inspection */
uint32_t sim_btr(uint8_t bus);
uint32_t sim_mcr(uint8_t bus);
uint32_t sim_fmr(void);
uint32_t sim_aborts(uint8_t bus);     /* mailboxes aborted by ABRQ       */
uint32_t sim_fault_bits(void);          /* stm32_fault_raise() so far      */
/* RX FIFO 0 handler runs of this bus (they run only when unmasked). */
uint32_t sim_rx_irq_runs(uint8_t bus);

extern uint32_t bxcan_sim_rcc[64];
#define SIM_RCC_APB1ENR_IDX (0x40U / 4U)

/* In bxcan.c under BXCAN_SIM: forget every bus's state. */
void bxcan_sim_driver_reset(void);

#endif /* BXCAN_SIM_H */
