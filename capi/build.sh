#!/usr/bin/env bash
# Builds the C API (run from anywhere):
#   host:  capi/target/release/libcontensou_capi.a (staticlib) and .so (cdylib),
#          capi/target/release/wrench_eval, rolling_eval and step_eval (the C twins of
#          `contact_eval wrench`, `contact_eval rolling` and `contact_eval step`)
#   MCU:   capi/target/thumbv7em-none-eabihf/release/libcontensou_capi.a
# and checks that the committed header is what cbindgen generates and that it compiles as
# C99 and C++17 with -Wall -Wextra -Werror -pedantic. `--no-check` skips the header checks.
set -euo pipefail
cd "$(dirname "$0")"
check=1
[[ "${1:-}" == "--no-check" ]] && check=0

if ((check)); then
    echo "capi: header is cbindgen's (cbindgen.toml)"
    generated="$(mktemp)"
    # nightly: cbindgen reads the macro-expanded crate (cbindgen.toml, [parse.expand])
    rustup toolchain list | grep -q '^nightly' || rustup toolchain install nightly --profile minimal
    RUSTUP_TOOLCHAIN=nightly cbindgen --quiet --config cbindgen.toml --output "$generated"
    if ! diff -u include/contensou.h "$generated"; then
        echo "capi: include/contensou.h is stale: run \`RUSTUP_TOOLCHAIN=nightly cbindgen --config cbindgen.toml --output include/contensou.h\` in capi/" >&2
        exit 1
    fi
    rm -f "$generated"
    echo "capi: header compiles as C99 and C++17 (-Wall -Wextra -Werror -pedantic)"
    probe="$(mktemp -d)"
    printf '#include "contensou.h"\nint main(void) { return (int)sizeof(contensou_contact_f64) == CONTENSOU_CONTACT_F64_SIZE ? 0 : 1; }\n' >"$probe/h.c"
    cp "$probe/h.c" "$probe/h.cpp"
    gcc -std=c99 -Wall -Wextra -Werror -pedantic -Iinclude -c "$probe/h.c" -o "$probe/c.o"
    g++ -std=c++17 -Wall -Wextra -Werror -pedantic -Iinclude -c "$probe/h.cpp" -o "$probe/cpp.o"
    rm -rf "$probe"
fi

echo "capi: host staticlib + cdylib"
cargo rustc --release --lib --crate-type staticlib,cdylib
echo "capi: thumbv7em-none-eabihf staticlib"
cargo rustc --release --lib --target thumbv7em-none-eabihf --crate-type staticlib

for twin in wrench_eval rolling_eval step_eval; do
    echo "capi: examples/$twin.c against the host staticlib"
    gcc -std=c99 -O2 -Wall -Wextra -Werror -pedantic -Iinclude "examples/$twin.c" \
        target/release/libcontensou_capi.a -lpthread -ldl -lm -o "target/release/$twin"
done

echo "capi: tests/errors.c (the error paths from C), plain and under ASan + UBSan"
san=(-fsanitize=address,undefined -fno-sanitize-recover=all)
gcc -std=c99 -Wall -Wextra -Werror -pedantic -Iinclude tests/errors.c target/release/libcontensou_capi.a \
    -lpthread -ldl -lm -o target/release/errors
target/release/errors
gcc -std=c99 -g "${san[@]}" -Iinclude tests/errors.c target/release/libcontensou_capi.a \
    -lpthread -ldl -lm -o target/release/errors-san
target/release/errors-san
echo "capi: tests/errors.c against the cdylib (which exports the contensou_* functions only)"
gcc -std=c99 -Wall -Wextra -Werror -pedantic -Iinclude tests/errors.c -Ltarget/release -lcontensou_capi \
    -Wl,-rpath,"$PWD/target/release" -o target/release/errors-dylib
target/release/errors-dylib
if nm -D --defined-only target/release/libcontensou_capi.so | awk '{ print $3 }' | grep -v '^contensou_'; then
    echo "capi: the cdylib exports symbols outside contensou_* (above)" >&2
    exit 1
fi
for twin in wrench_eval rolling_eval step_eval; do
    gcc -std=c99 -g "${san[@]}" -Iinclude "examples/$twin.c" target/release/libcontensou_capi.a \
        -lpthread -ldl -lm -o "target/release/$twin-san"
done

echo "capi: every C block of the README and the guide (docs/guide/src/*.md) compiles (C99 and C++17) and runs"
blocks="$(mktemp -d)"
for doc in ../README.md ../docs/guide/src/*.md; do
    name="$(basename "$doc" .md)"
    awk -v out="$blocks/$name" '/^```c$/ { n++; p = 1; f = sprintf("%s-%d.c", out, n); next }
        p && /^```$/ { p = 0; next } p { print > f }' "$doc"
done
count=0
for c in "$blocks"/*.c; do
    [[ -e "$c" ]] || continue
    count=$((count + 1))
    gcc -std=c99 -Wall -Wextra -Werror -pedantic -Iinclude "$c" target/release/libcontensou_capi.a \
        -lpthread -ldl -lm -o "${c%.c}"
    cp "$c" "${c%.c}.cpp"
    g++ -std=c++17 -Wall -Wextra -Werror -pedantic -Iinclude -c "${c%.c}.cpp" -o "${c%.c}.o"
    "${c%.c}" >/dev/null || { echo "capi: C block $(basename "$c") failed" >&2; exit 1; }
done
echo "capi: $count C blocks compiled and run"
((count >= 2)) || { echo "capi: expected the README's and the guide's C blocks, found $count" >&2; exit 1; }
rm -rf "$blocks"
