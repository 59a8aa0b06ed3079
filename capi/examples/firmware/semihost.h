/* ARM semihosting (QEMU -semihosting-config enable=on): buffered writes to the host's stdout
 * and the exit status, the way the Rust rig's cortex-m-semihosting does it (SYS_OPEN ":tt",
 * SYS_WRITE, SYS_EXIT). */
#ifndef SEMIHOST_H
#define SEMIHOST_H

#include <stdint.h>

/* Appends to the output buffer (flushed by one SYS_WRITE when full, and by sh_flush). */
void sh_puts(const char *s);
/* `x` as eight lowercase hex digits. */
void sh_hex32(uint32_t x);
/* `x` in decimal. */
void sh_u32(uint32_t x);
/* Writes out the buffer; 0 on success. */
int sh_flush(void);
/* Flushes, then ends the QEMU run: status 0 = success, anything else = failure. */
__attribute__((noreturn)) void sh_exit(int status);

#endif
