/* SPDX-License-Identifier: MIT */
/*
 * A simulated pair of STM32G474 FDCAN instances (FDCAN1, FDCAN2) with their
 * message RAM and wires, written from RM0440 chapter 44 and independent of
 * hal/stm32g4/fdcan.c: the driver, built with -DFDCAN_SIM, reads and writes
 * these registers and RAM words as it would the chip's, and the simulation
 * behaves as the manual says: CCCR.INIT/CCE and the protected fields, the
 * registers CCE holds in reset, write-1-to-clear IR, PSR's LEC/DLEC/PXE
 * reset on read, the RX FIFO 0 fill/get/put indices and acknowledge
 * (blocking mode: message lost), the TX FIFO put index and requests,
 * the standard and extended filter lists (all filter types, RXGFC's
 * non-matching and remote rules, XIDAM), bus monitoring mode (no ACK, no
 * error flag, no transmission), internal and external loopback, error
 * counters with the warning/passive limits, bus-off with INIT set by the
 * controller and recovery only once software has cleared INIT. Each
 * instance has its own wire, or both share one (the other instance is the
 * bus). Interrupt line 0 runs the driver's handler when IE, ILE, the NVIC
 * and the interrupt mask let it.
 */
#ifndef FDCAN_SIM_H
#define FDCAN_SIM_H

#include <stdbool.h>
#include <stdint.h>

#include "hal.h"

#define SIM_BUSES 2U

/* Everything back to reset (registers, RAM, wires, clock, NVIC, counters)
 * and the driver's own state (fdcan_sim_driver_reset). */
void sim_reset(void);
/* The FDCAN kernel clock chip_fdcan_kernel_hz() reports (170 MHz after reset). */
void sim_set_kernel_hz(uint32_t hz);

/* Both instances on one wire: what one sends the other receives (and
 * acknowledges, unless it is in bus monitoring mode or not running). */
void sim_connect(bool on);

/* Another node sends this frame on `bus`'s wire. Returns true when some
 * controller acknowledged it. */
bool sim_inject(uint8_t bus, const hal_can_frame_t *f);
/* Oldest frame a controller put on the wire of `bus`. */
bool sim_wire_take(uint8_t bus, hal_can_frame_t *f);
uint32_t sim_wire_count(uint8_t bus);
/* Dominant bits the controller drove other than its own frames: ACKs and
 * error flags (bus monitoring mode must leave this at 0). */
uint32_t sim_dominant_count(uint8_t bus);

void sim_error_frame(uint8_t bus);           /* a stuff error seen, REC + 1 */
void sim_set_counters(uint8_t bus, uint32_t tec, uint32_t rec);
void sim_protocol_exception(uint8_t bus);
/* on: TEC > 255, the controller goes bus-off and sets INIT. off: 129 x 11
 * recessive bits have passed; the controller recovers only if software
 * has cleared INIT. Returns true when it is (still or now) not bus-off. */
bool sim_bus_off(uint8_t bus, bool on);
/* Nothing acknowledges this controller's frames: they stay pending. */
void sim_block_tx(uint8_t bus, bool blocked);
/* The controller ignores INIT (no clock, QEMU). */
void sim_controller_dead(uint8_t bus, bool dead);

void sim_advance_us(uint32_t us);
uint64_t sim_now_us(void);

/* Inspection */
uint32_t sim_reg(uint8_t bus, uint32_t off);   /* without read side effects */
uint32_t sim_ram(uint8_t bus, uint32_t byte_off);
uint32_t sim_fault_bits(void);
uint32_t sim_irq_runs(uint8_t bus);
uint32_t sim_rx_lost(uint8_t bus);           /* frames the FIFO could not take */
uint32_t sim_protected_writes_ignored(uint8_t bus);

/* In fdcan.c under FDCAN_SIM: forget every bus's state. */
void fdcan_sim_driver_reset(void);

#endif /* FDCAN_SIM_H */
