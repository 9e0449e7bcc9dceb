/* SPDX-License-Identifier: MIT */
/*
 * Positive control of tests/system/static/cppcheck-misra.sh: every line marked
 * "canary:" breaks the rules it names on purpose: at least one rule of each
 * MISRA C:2012 chapter the project is checked for, and one finding of each
 * cppcheck check class it enables (error, warning, style, portability). The
 * check runs cppcheck + the MISRA addon on this file with the project's
 * options and no deviations, and fails unless the findings are exactly the
 * marked (line, id) pairs: a missed one means the addon or cppcheck stopped
 * checking. Never compiled, never linked.
 */
#include <stdint.h>
#include <stdio.h> /* canary: misra-c2012-21.6 */

#define CANARY_UNUSED 1 /* canary: misra-c2012-2.5 */
#define CANARY_SQ(x) (x * x) /* canary: misra-c2012-20.7 */

int32_t canary_octal(void);
int32_t canary_shift(int32_t x);
int32_t canary_return(int32_t x);
int32_t canary_switch(int32_t x);
void canary_param(int32_t x);
int32_t canary_ptr(const int32_t *p);
int32_t canary_uninit(void);
int32_t canary_cond(int32_t x);
int32_t canary_prec(int32_t a, int32_t b);
uintptr_t canary_addr(const int32_t *p);
int32_t canary_macro(int32_t x);
int32_t canary_store(void);
void canary_discard(void);
int32_t canary_port(int32_t *p);

int32_t canary_octal(void) /* canary: misra-c2012-8.7 */
{
	return 010; /* canary: misra-c2012-7.1 */
}

int32_t canary_shift(int32_t x)
{
	return x << 2; /* canary: misra-c2012-10.1 */
}

int32_t canary_return(int32_t x)
{
	if (x > 0) {
		return 1; /* canary: misra-c2012-15.5 */
	}
	return 0;
}

int32_t canary_switch(int32_t x)
{
	int32_t r = 0;

	switch (x) { /* canary: misra-c2012-16.4 */
	case 1:
		r = 2;
		break;
	}
	return r;
}

void canary_param(int32_t x)
{
	x = 3; /* canary: misra-c2012-17.8 */
	(void)x;
}

int32_t canary_ptr(const int32_t *p)
{
	const int32_t *q = p + 1; /* canary: misra-c2012-18.4 */
	return *q;
}

int32_t canary_uninit(void)
{
	int32_t v; /* canary: unassignedVariable */
	return v; /* canary: uninitvar */
}

int32_t canary_cond(int32_t x)
{
	int32_t r = 0;

	if (x) { /* canary: misra-c2012-14.4 */
		r = 1;
	}
	return r;
}

int32_t canary_prec(int32_t a, int32_t b)
{
	return a + b * 2; /* canary: misra-c2012-12.1 */
}

uintptr_t canary_addr(const int32_t *p)
{
	return (uintptr_t)p; /* canary: misra-c2012-11.4 */
}

int32_t canary_macro(int32_t x)
{
	return CANARY_SQ(x);
}

int32_t canary_store(void)
{
	int32_t unread = 5; /* canary: unreadVariable */
	int32_t r = 1;

	if ((r == 1) && (r == 2)) { /* canary: incorrectLogicOperator knownConditionTrueFalse */
		r = 3;
	}
	return r;
}

int32_t canary_nodecl(void) /* canary: misra-c2012-8.4 */
{
	return 0;
}

void canary_discard(void)
{
	canary_octal(); /* canary: misra-c2012-17.7 */
}

int32_t canary_port(int32_t *p)
{
	const float *f = (const float *)p; /* canary: invalidPointerCast misra-c2012-11.3 */

	return (int32_t)*f;
}
