/* SPDX-License-Identifier: MIT */
/*
 * STM32F405 CAN pins and clocks (hal/stm32f4/can_pins.c) on the host, RCC
 * and GPIOB in plain arrays (tests/support/regsim/f4/chip.h). Expected
 * register values by hand from the datasheet's table 9 (CAN1 RX PB8, TX
 * PB9; CAN2 RX PB12, TX PB13; all AF9) and RM0090 section 8.4: MODER 2 bits
 * a pin (10 = alternate function), OTYPER 1 bit (0 = push-pull), OSPEEDR 2
 * bits (10 = high speed), PUPDR 2 bits (01 = pull-up), AFRH 4 bits a pin
 * for pins 8..15; RCC_AHB1ENR bit 1 GPIOBEN, RCC_APB1ENR bit 25 CAN1EN,
 * bit 26 CAN2EN (CAN2 needs CAN1's clock: its filters are CAN1's).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "sq_cmocka.h"

#include "chip.h"

#define AHB1ENR regsim_rcc[0x30U / 4U]
#define APB1ENR regsim_rcc[0x40U / 4U]
#define MODER   regsim_gpiob[0x00U / 4U]
#define OTYPER  regsim_gpiob[0x04U / 4U]
#define OSPEEDR regsim_gpiob[0x08U / 4U]
#define PUPDR   regsim_gpiob[0x0CU / 4U]
#define AFRL    regsim_gpiob[0x20U / 4U]
#define AFRH    regsim_gpiob[0x24U / 4U]

static void test_can1_on_pb8_pb9(void **state)
{
	(void)state;
	chip_can_pins_init(0U);
	assert_int_equal(AHB1ENR, 0x00000002U);
	assert_int_equal(APB1ENR, 0x02000000U);
	assert_int_equal(MODER, 0x000A0000U);   /* pins 8, 9: 10 */
	assert_int_equal(OSPEEDR, 0x000A0000U);
	assert_int_equal(PUPDR, 0x00010000U);   /* pull-up on PB8 (RX) only */
	assert_int_equal(OTYPER, 0U);
	assert_int_equal(AFRH, 0x00000099U);    /* AF9 on pins 8 and 9 */
	assert_int_equal(AFRL, 0U);
}

static void test_can2_on_pb12_pb13_with_can1_clock(void **state)
{
	(void)state;
	chip_can_pins_init(1U);
	assert_int_equal(AHB1ENR, 0x00000002U);
	assert_int_equal(APB1ENR, 0x06000000U);
	assert_int_equal(MODER, 0x0A000000U);   /* pins 12, 13 */
	assert_int_equal(OSPEEDR, 0x0A000000U);
	assert_int_equal(PUPDR, 0x01000000U);   /* pull-up on PB12 (RX) */
	assert_int_equal(AFRH, 0x00990000U);
}

static void test_other_pins_and_bits_kept(void **state)
{
	(void)state;
	/* pin 8 was an output with pull-down and AF3, pin 0 an output, PB9
	 * open-drain, another clock enabled: only the CAN pins' fields change */
	MODER = 0x00010001U;
	PUPDR = 0x00020000U;
	AFRH = 0x00000003U;
	OTYPER = 0x00000201U;
	APB1ENR = 0x10000000U;
	chip_can_pins_init(0U);
	assert_int_equal(MODER, 0x000A0001U);
	assert_int_equal(PUPDR, 0x00010000U);
	assert_int_equal(AFRH, 0x00000099U);
	assert_int_equal(OTYPER, 0x00000001U);
	assert_int_equal(APB1ENR, 0x12000000U);
}

static void test_a_bus_the_chip_lacks_touches_nothing(void **state)
{
	(void)state;
	chip_can_pins_init(2U);
	chip_can_pins_init(255U);
	assert_int_equal(AHB1ENR, 0U);
	assert_int_equal(APB1ENR, 0U);
	assert_int_equal(MODER, 0U);
	assert_int_equal(AFRH, 0U);
}

SQ_CMOCKA_MAIN(
	cmocka_unit_test_setup(test_can1_on_pb8_pb9, regsim_f4_setup),
	cmocka_unit_test_setup(test_can2_on_pb12_pb13_with_can1_clock, regsim_f4_setup),
	cmocka_unit_test_setup(test_other_pins_and_bits_kept, regsim_f4_setup),
	cmocka_unit_test_setup(test_a_bus_the_chip_lacks_touches_nothing, regsim_f4_setup))
