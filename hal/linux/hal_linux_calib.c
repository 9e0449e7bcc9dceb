/* SPDX-License-Identifier: MIT */
/*
 * hal_linux_calib.c: the calibration block in a file, and the reset reason.
 *
 * The file holds exactly the bytes last written. A write goes to a temporary
 * file in the same directory, is fsync()ed, renamed over the old file (an
 * atomic replace on POSIX file systems) and the directory is fsync()ed: after
 * a crash or power loss at any point the path names either the complete old
 * block or the complete new one. The written file is then read back and
 * compared (the flash backend's "verify").
 *
 * A read of len bytes from a shorter file returns the stored bytes followed
 * by 0xFF, as erased flash reads: the block's own length and CRC (calib.c)
 * decide whether it is valid.
 */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "hal_linux.h"

static char calib_path[PATH_MAX];
static hal_reset_reason_t reset_reason = HAL_RESET_POWER_ON;

int hal_linux_set_calib_path(const char *path)
{
	size_t len;

	if (path == NULL) {
		calib_path[0] = '\0';
		return SQ_OK;
	}
	len = strlen(path);
	/* Room for the temporary file's ".tmp.<pid>" suffix too. */
	if (len + 32U >= sizeof(calib_path)) {
		hal_linux_set_error("calibration path too long: %.64s...", path);
		return SQ_EINVAL;
	}
	memcpy(calib_path, path, len + 1U);
	return SQ_OK;
}

/* read() until len bytes or end of file; returns bytes read or -1. */
static ssize_t read_full(int fd, uint8_t *buf, size_t len)
{
	size_t got = 0;

	while (got < len) {
		ssize_t n = read(fd, buf + got, len - got);

		if (n < 0 && errno == EINTR) {
			continue;
		}
		if (n < 0) {
			return -1;
		}
		if (n == 0) {
			break;
		}
		got += (size_t)n;
	}
	return (ssize_t)got;
}

static int write_full(int fd, const uint8_t *buf, size_t len)
{
	size_t put = 0;

	while (put < len) {
		ssize_t n = write(fd, buf + put, len - put);

		if (n < 0 && errno == EINTR) {
			continue;
		}
		if (n <= 0) {
			return -1;
		}
		put += (size_t)n;
	}
	return 0;
}

int hal_calib_read(uint8_t *buf, uint32_t len)
{
	uint8_t file_buf[HAL_CALIB_MAX_LEN + 1U];
	ssize_t got;
	int fd;

	if (buf == NULL || len == 0U || len > HAL_CALIB_MAX_LEN) {
		return SQ_EINVAL;
	}
	if (calib_path[0] == '\0') {
		return SQ_ENOENT;
	}
	fd = open(calib_path, O_RDONLY | O_CLOEXEC);
	if (fd < 0) {
		if (errno == ENOENT) {
			return SQ_ENOENT;
		}
		hal_linux_set_error("calibration file %s: %s", calib_path, strerror(errno));
		hal_linux_add_fault(HAL_FAULT_CALIB_STORAGE);
		return SQ_EIO;
	}
	got = read_full(fd, file_buf, sizeof(file_buf));
	(void)close(fd);
	if (got < 0) {
		hal_linux_set_error("calibration file %s: read: %s", calib_path, strerror(errno));
		hal_linux_add_fault(HAL_FAULT_CALIB_STORAGE);
		return SQ_EIO;
	}
	if (got == 0) {
		return SQ_ENOENT;
	}
	if ((size_t)got > HAL_CALIB_MAX_LEN) {
		hal_linux_set_error("calibration file %s: larger than %u bytes: not a calibration block",
				    calib_path, HAL_CALIB_MAX_LEN);
		return SQ_EIO;
	}
	memset(buf, 0xFF, len);
	memcpy(buf, file_buf, (size_t)got < len ? (size_t)got : len);
	return SQ_OK;
}

/* The directory part of calib_path, for fsync after the rename. */
static int open_parent_dir(void)
{
	char dir[PATH_MAX];
	char *slash;

	memcpy(dir, calib_path, sizeof(dir));
	slash = strrchr(dir, '/');
	if (slash == NULL) {
		return open(".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	}
	if (slash == dir) {
		slash[1] = '\0';
	} else {
		slash[0] = '\0';
	}
	return open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
}

static int calib_write_fail(const char *tmp_path, const char *what, int err)
{
	hal_linux_set_error("calibration file %s: %s: %s", calib_path, what, strerror(err));
	hal_linux_add_fault(HAL_FAULT_CALIB_STORAGE);
	if (tmp_path != NULL) {
		(void)unlink(tmp_path);
	}
	return SQ_EIO;
}

int hal_calib_write(const uint8_t *buf, uint32_t len)
{
	char tmp_path[PATH_MAX];
	uint8_t check[HAL_CALIB_MAX_LEN];
	int fd;
	int n;
	int rc;

	if (buf == NULL || len == 0U || len > HAL_CALIB_MAX_LEN) {
		return SQ_EINVAL;
	}
	if (calib_path[0] == '\0') {
		hal_linux_set_error("no calibration file set (hal_linux_set_calib_path)");
		return SQ_EIO;
	}
	n = snprintf(tmp_path, sizeof(tmp_path), "%s.tmp.%ld", calib_path, (long)getpid());
	if (n < 0 || (size_t)n >= sizeof(tmp_path)) {
		return calib_write_fail(NULL, "temporary name", ENAMETOOLONG);
	}
	fd = open(tmp_path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
	if (fd < 0) {
		return calib_write_fail(NULL, "create temporary file", errno);
	}
	if (write_full(fd, buf, len) != 0) {
		int err = errno;

		(void)close(fd);
		return calib_write_fail(tmp_path, "write", err);
	}
	if (fsync(fd) != 0) {
		int err = errno;

		(void)close(fd);
		return calib_write_fail(tmp_path, "fsync", err);
	}
	if (close(fd) != 0) {
		return calib_write_fail(tmp_path, "close", errno);
	}
	if (rename(tmp_path, calib_path) != 0) {
		return calib_write_fail(tmp_path, "rename", errno);
	}
	fd = open_parent_dir();
	if (fd >= 0) {
		/* Makes the rename durable; some file systems refuse fsync on
		 * a directory (EINVAL), which loses nothing already written. */
		(void)fsync(fd);
		(void)close(fd);
	}
	rc = hal_calib_read(check, len);
	if (rc != SQ_OK || memcmp(check, buf, len) != 0) {
		hal_linux_set_error("calibration file %s: read-back differs from what was written",
				    calib_path);
		hal_linux_add_fault(HAL_FAULT_CALIB_STORAGE);
		return SQ_EIO;
	}
	return SQ_OK;
}

void hal_linux_set_reset_reason(hal_reset_reason_t reason)
{
	reset_reason = reason;
}

hal_reset_reason_t hal_reset_reason(void)
{
	return reset_reason;
}
