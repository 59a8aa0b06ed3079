#!/usr/bin/env bash
# Builds the C firmware images against the C API's thumbv7em-none-eabihf staticlib:
#   capi/target/firmware/bits.elf    host = MCU bit-identity stream (bits.c, vectors.c)
#   capi/target/firmware/bench.elf   wrench instruction counts (bench.c)
# C startup, vector table and linker script: startup.c, link.ld (memory map: ../../../memory.x).
# Run them with QEMU as the Rust rig does (tools/qemu-bench.sh runs bench.elf,
# tools/host-mcu-bits.sh bits.elf). Needs gcc-arm-none-eabi (apt; libnewlib-arm-none-eabi for
# the <math.h>/<stdint.h> headers only) and rustup. Writes capi/target/firmware/size.txt.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
capi="$here/../.."
root="$capi/.."
out="$capi/target/firmware"
mkdir -p "$out"

# The Rust staticlib (release: opt-level 3, fat LTO, panic = abort; see capi/Cargo.toml), with
# the Rust rig's pinned compiler (firmware/rust-toolchain.toml) so that C and Rust rows compare.
chan="$(sed -n 's/^channel *= *"\(.*\)"/\1/p' "$root/firmware/rust-toolchain.toml")"
rustup toolchain list | grep -q "^$chan" || rustup toolchain install "$chan" --profile minimal
rustup target list --installed --toolchain "$chan" | grep -q '^thumbv7em-none-eabihf$' ||
    rustup target add --toolchain "$chan" thumbv7em-none-eabihf
(cd "$capi" && cargo "+$chan" rustc --release --quiet --lib --target thumbv7em-none-eabihf \
    --crate-type staticlib)
lib="$capi/target/thumbv7em-none-eabihf/release/libcontensou_capi.a"

# The Rust library's FPU ABI; -ffp-contract=off: no fused multiply-add that the Rust code,
# which never contracts, would not have (it matters only to C arithmetic: vectors.c, bench.c).
cflags=(-mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard -mthumb -O2 -g -std=c99
    -Wall -Wextra -Werror -pedantic -ffp-contract=off -ffunction-sections -fdata-sections
    -ffreestanding -I"$capi/include")
mkdir -p "$out/obj"
for c in startup semihost counter vectors bits bench; do
    arm-none-eabi-gcc "${cflags[@]}" -c "$here/$c.c" -o "$out/obj/$c.o"
done
o="$out/obj"

# link IMAGE OBJECTS… LIBRARIES…: the ELF and its link map.
link() {
    local image="$1"
    shift
    arm-none-eabi-gcc "${cflags[@]}" -nostartfiles -T"$here/link.ld" -L"$root" \
        -Wl,--gc-sections -Wl,--no-warn-rwx-segments -Wl,--no-warn-execstack \
        -Wl,-Map="$out/$image.map" -o "$out/$image.elf" "$@"
}
# No C library: the images call no libc function, and bench.c's pow/sin/cos (the input set,
# computed once before measuring) resolve to the C math symbols that the staticlib's
# compiler_builtins exports — the Rust libm code the Rust rig computes the same set with.
link bits -nostdlib "$o/startup.o" "$o/semihost.o" "$o/vectors.o" "$o/bits.o" "$lib" -lgcc
link bench -nostdlib "$o/startup.o" "$o/semihost.o" "$o/counter.o" "$o/bench.o" "$lib" -lgcc

# Flash bytes (text + data: .vectors, .text, .rodata, .ARM.exidx and .data's load image) per
# image and per input file, from the link maps.
{
    echo "# C firmware images (capi/examples/firmware/build.sh; $(arm-none-eabi-gcc --version | head -n 1);"
    echo "# Rust $chan, capi release profile). Flash = text + data, per image and per input file."
    for image in bits bench; do
        arm-none-eabi-size -A "$out/$image.elf" |
            awk -v img="$image" '$1 ~ /^\.(vectors|text|rodata|ARM\.exidx|data)$/ { s += $2 }
                END { printf "%s.elf: %d bytes of flash (text + data)\n", img, s }'
        awk '/^Linker script and memory map/ { on = 1 }
            on && /^ \.(vectors|text|rodata|ARM\.exidx|data)/ {
                if (NF >= 4) { add($3, $4) } else { pending = 1 }; next }
            on && pending && /^ +0x/ { add($2, $3); pending = 0; next }
            { pending = 0 }
            function add(size, file) {
                sub(/^.*\//, "", file)
                if (file ~ /\(compiler_builtins-/) file = "libcontensou_capi.a: compiler_builtins (soft-float, mem*, math symbols)"
                else if (file ~ /\(contensou_capi-/) file = "libcontensou_capi.a: contensou + contensou-capi (one LTO object)"
                bytes[file] += hex(size) }
            function hex(x,   n, i) { n = 0; for (i = 3; i <= length(x); i++)
                n = n * 16 + index("0123456789abcdef", substr(tolower(x), i, 1)) - 1; return n }
            END { for (f in bytes) if (bytes[f] > 0) printf "  %7d  %s\n", bytes[f], f }' \
            "$out/$image.map" | sort -rn
    done
} >"$out/size.txt"
cat "$out/size.txt"
