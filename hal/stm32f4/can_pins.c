/* SPDX-License-Identifier: MIT */
/*
 * STM32F405/407 CAN pins and clocks (datasheet table 9, RM0090 section 7):
 *   CAN1: PB8 = RX, PB9 = TX, AF9.
 *   CAN2: PB12 = RX, PB13 = TX, AF9 (default), or PB5 = RX, PB6 = TX, AF9
 *         when built with -DSQ_CAN2_PINS_PB5_PB6 (a board choice).
 * CAN2 is a slave of CAN1: its filter banks are CAN1's registers, so CAN1's
 * clock is enabled for either bus.
 */
#include "chip.h"

typedef struct {
	uint8_t rx_pin;
	uint8_t tx_pin;
	uint32_t clock_en;
} can_pins_t;

static const can_pins_t can_pins[CHIP_CAN_BUSES] = {
	{ 8U, 9U, RCC_APB1ENR_CAN1EN },
#if defined(SQ_CAN2_PINS_PB5_PB6)
	{ 5U, 6U, RCC_APB1ENR_CAN1EN | RCC_APB1ENR_CAN2EN },
#else
	{ 12U, 13U, RCC_APB1ENR_CAN1EN | RCC_APB1ENR_CAN2EN },
#endif
};

static void field_set(uintptr_t reg_addr, uint32_t shift, uint32_t width_mask, uint32_t value)
{
	uint32_t v = REG32(reg_addr) & ~(width_mask << shift);

	REG32(reg_addr) = v | (value << shift);
}

/* Port B pin in alternate function 9, high speed, push-pull; pull-up on
 * RX (recessive while no transceiver drives it). */
static void pin_af9(uint32_t pin, bool pull_up)
{
	uintptr_t afr = (uintptr_t)&GPIO_AFRL(GPIOB_BASE) + (pin >= 8U ? 4U : 0U);

	field_set(afr, 4U * (pin & 7U), 0xFU, GPIO_AF9_CAN1);
	field_set((uintptr_t)&GPIO_MODER(GPIOB_BASE), 2U * pin, 3U, GPIO_MODE_AF);
	field_set((uintptr_t)&GPIO_OSPEEDR(GPIOB_BASE), 2U * pin, 3U, GPIO_SPEED_HIGH);
	field_set((uintptr_t)&GPIO_OTYPER(GPIOB_BASE), pin, 1U, 0U);
	field_set((uintptr_t)&GPIO_PUPDR(GPIOB_BASE), 2U * pin, 3U, pull_up ? GPIO_PUPD_UP : 0U);
}

void chip_can_pins_init(uint8_t bus)
{
	const can_pins_t *p;

	if (bus >= CHIP_CAN_BUSES) {
		return;
	}
	p = &can_pins[bus];
	RCC_AHB1ENR |= RCC_AHB1ENR_GPIOBEN;
	RCC_APB1ENR |= p->clock_en;
	(void)RCC_APB1ENR; /* read back: the enable needs two cycles */
	pin_af9(p->rx_pin, true);
	pin_af9(p->tx_pin, false);
}
