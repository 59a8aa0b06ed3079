/* See semihost.h. */
#include "semihost.h"

#define SYS_OPEN 0x01
#define SYS_WRITE 0x05
#define SYS_EXIT 0x18
#define ADP_STOPPED_APPLICATION_EXIT 0x20026
#define ADP_STOPPED_RUNTIME_ERROR_UNKNOWN 0x20023

static uint32_t call(uint32_t op, const void *arg) {
    register uint32_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

static char buf[4096];
static uint32_t len;
static int failed;

int sh_flush(void) {
    static int32_t handle = -1;
    if (handle < 0) {
        const uintptr_t open[3] = {(uintptr_t)":tt", 4 /* "w" */, 3};
        handle = (int32_t)call(SYS_OPEN, open);
    }
    if (len > 0) {
        const uintptr_t write[3] = {(uintptr_t)handle, (uintptr_t)buf, len};
        failed |= handle < 0 || call(SYS_WRITE, write) != 0; /* returns bytes NOT written */
        len = 0;
    }
    return failed;
}

static void put(char c) {
    if (len == sizeof buf) sh_flush();
    buf[len++] = c;
}

void sh_puts(const char *s) {
    while (*s) put(*s++);
}

void sh_hex32(uint32_t x) {
    for (int shift = 28; shift >= 0; shift -= 4) put("0123456789abcdef"[(x >> shift) & 0xF]);
}

void sh_u32(uint32_t x) {
    char digits[10];
    int n = 0;
    do {
        digits[n++] = (char)('0' + x % 10);
        x /= 10;
    } while (x);
    while (n) put(digits[--n]);
}

void sh_exit(int status) {
    if (sh_flush()) status = 1;
    /* On 32-bit ARM the reason code itself is the argument; QEMU exits 0 for ApplicationExit,
     * 1 for any other reason. */
    call(SYS_EXIT, (const void *)(uintptr_t)(status == 0 ? ADP_STOPPED_APPLICATION_EXIT
                                                         : ADP_STOPPED_RUNTIME_ERROR_UNKNOWN));
    for (;;) {
    }
}
