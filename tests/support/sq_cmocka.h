/* SPDX-License-Identifier: MIT */
/*
 * The one main() of a cmocka test program: its tests, one per line, run as
 * one group (cmocka prints the count tests/run-tests.sh reads; the exit
 * status is the number that failed).
 *
 *   SQ_CMOCKA_MAIN(
 *	cmocka_unit_test(test_a),
 *	cmocka_unit_test_setup(test_b, setup))
 */
#ifndef SQ_CMOCKA_H
#define SQ_CMOCKA_H

#define SQ_CMOCKA_MAIN(...)                                        \
	int main(void)                                             \
	{                                                          \
		const struct CMUnitTest tests[] = { __VA_ARGS__ }; \
		return cmocka_run_group_tests(tests, NULL, NULL);  \
	}

#endif /* SQ_CMOCKA_H */
