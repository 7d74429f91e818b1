/* perf_counter.c - one user-space instruction counter via perf_event_open(2). */
#define _GNU_SOURCE /* syscall() */
#include "perf_counter.h"

#include <linux/perf_event.h>
#include <stdint.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/syscall.h>
#include <unistd.h>

int perf_counter_open(struct perf_counter *c) {
    struct perf_event_attr attr;
    memset(&attr, 0, sizeof attr);
    attr.size = sizeof attr;
    attr.type = PERF_TYPE_HARDWARE;
    attr.config = PERF_COUNT_HW_INSTRUCTIONS;
    attr.disabled = 1;
    /* User space only: allowed at perf_event_paranoid 2, and it is the code
     * being compared; page faults are kernel work and show up in the time. */
    attr.exclude_kernel = 1;
    attr.exclude_hv = 1;
    /* Running times, to scale the count if the kernel multiplexed the counter. */
    attr.read_format = PERF_FORMAT_TOTAL_TIME_ENABLED | PERF_FORMAT_TOTAL_TIME_RUNNING;
    /* This process, any CPU, no group, no flags. glibc has no wrapper. */
    c->fd = (int)syscall(SYS_perf_event_open, &attr, 0, -1, -1, 0UL);
    return c->fd >= 0 ? 0 : -1;
}

void perf_counter_start(struct perf_counter *c) {
    if (c->fd < 0) return;
    ioctl(c->fd, PERF_EVENT_IOC_RESET, 0);
    ioctl(c->fd, PERF_EVENT_IOC_ENABLE, 0);
}

double perf_counter_stop(struct perf_counter *c) {
    uint64_t value[3]; /* count, time enabled, time running */
    if (c->fd < 0) return -1.0;
    ioctl(c->fd, PERF_EVENT_IOC_DISABLE, 0);
    if (read(c->fd, value, sizeof value) != (ssize_t)sizeof value || value[2] == 0) return -1.0;
    if (value[2] == value[1]) return (double)value[0];
    return (double)value[0] * ((double)value[1] / (double)value[2]);
}

void perf_counter_close(struct perf_counter *c) {
    if (c->fd >= 0) close(c->fd);
    c->fd = -1;
}
