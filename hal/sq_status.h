/* SPDX-License-Identifier: MIT */
/*
 * One error convention for the whole project (firmware, HALs, host tools):
 * 0 is success, a negative value names the failure. The numbers follow
 * Linux errno so a host log reads naturally, but firmware/ does not include
 * <errno.h> (it is not a freestanding header).
 */
#ifndef SQ_STATUS_H
#define SQ_STATUS_H

#define SQ_OK            0
#define SQ_EPERM        (-1)   /* not allowed (send on a listen-only bus)  */
#define SQ_ENOENT       (-2)   /* nothing stored / no such item            */
#define SQ_EIO          (-5)   /* hardware or storage failure              */
#define SQ_ENODEV      (-19)   /* no such device (a bus this chip lacks)   */
#define SQ_EAGAIN      (-11)   /* nothing now (RX empty) or timed out      */
#define SQ_EINVAL      (-22)   /* bad argument or implausible value        */
#define SQ_ERANGE      (-34)   /* value outside the representable range    */
#define SQ_EBADMSG     (-74)   /* malformed message / failed CRC           */
#define SQ_ENETDOWN   (-100)   /* controller stopped / interface down      */
#define SQ_ENETUNREACH (-101)  /* bus-off                                  */
#define SQ_ENOBUFS    (-105)   /* queue full                               */
#define SQ_ENOTSUP     (-95)   /* not supported by this backend            */

#endif /* SQ_STATUS_H */
