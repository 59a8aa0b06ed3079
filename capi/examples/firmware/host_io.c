/* semihost.h on a hosted C library, so that bits.c and vectors.c also run on the host
 * (x86-64, linked against the host staticlib of the C API): tools/host-mcu-bits.sh compares
 * that stream too. The MCU images use semihost.c instead. */
#include <stdio.h>
#include <stdlib.h>

#include "semihost.h"

void sh_puts(const char *s) { fputs(s, stdout); }

void sh_hex32(uint32_t x) { printf("%08lx", (unsigned long)x); }

void sh_u32(uint32_t x) { printf("%lu", (unsigned long)x); }

int sh_flush(void) { return fflush(stdout) != 0 || ferror(stdout); }

void sh_exit(int status) { exit(sh_flush() ? 1 : status); }
