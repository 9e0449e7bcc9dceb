/* SPDX-License-Identifier: MIT */
/* The version of squeal-sim and its programs: this is the one place it is
 * written (`squeal-sim --version` prints it with the numeric build). */
#ifndef SIM_VERSION_H
#define SIM_VERSION_H

#define SQUEAL_SIM_VERSION "1.0.0"

#endif /* SIM_VERSION_H */
