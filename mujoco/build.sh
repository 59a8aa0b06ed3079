#!/usr/bin/env bash
# Builds the MuJoCo engine plugin `contensou.contact` (run from anywhere):
#   mujoco/build/libcontensou_mujoco.so   the plugin (C, capi's staticlib linked in; exports no symbol
#                                         but its load-time registration)
#   mujoco/build/run_model                 examples/run_model.c: loads the plugin and a model from C
# and runs the four models from C with the plugin and the runner under ASan + UBSan (leaks too),
# plus a refused model (its message checked); `--no-check` skips that.
# against the `mujoco` Python package of $PYTHON (default: python3; headers from mujoco.HEADERS_DIR,
# its libmujoco.so.*), and the C API's host staticlib (capi/, built here with cargo).
set -euo pipefail
cd "$(dirname "$0")"
python="${PYTHON:-python3}"
check=1
[[ "${1:-}" == "--no-check" ]] && check=0

pkg="$("$python" -c 'import mujoco, os; print(os.path.dirname(mujoco.__file__))')"
headers="$("$python" -c 'import mujoco; print(mujoco.HEADERS_DIR)')"
lib="$(ls "$pkg"/libmujoco.so.* 2>/dev/null | head -n 1)"
[[ -f "$headers/mujoco.h" && -f "$lib" ]] || { echo "mujoco/build.sh: no mujoco headers/library under $pkg" >&2; exit 1; }
version="$("$python" -c 'import mujoco; print(mujoco.__version__)')"
echo "mujoco: building against MuJoCo $version ($lib)"

echo "mujoco: capi host staticlib"
(cd ../capi && cargo rustc --quiet --release --lib --crate-type staticlib)
capi=../capi/target/release/libcontensou_capi.a

mkdir -p build
flags=(-std=c11 -O2 -fPIC -ffp-contract=off -Wall -Wextra -Werror -pedantic -Wno-overlength-strings
       -I"$(dirname "$headers")" -I../capi/include)
# -ffp-contract=off: no fused multiply-add, so that the arithmetic is that of the Python callback
# (python/examples/floor_contact.py) on every host; --exclude-libs: the Rust staticlib's symbols stay local.
gcc "${flags[@]}" -fvisibility=hidden -shared src/*.c "$capi" "$lib" \
    -Wl,--exclude-libs,ALL -Wl,-z,defs -Wl,-rpath,"$pkg" -lpthread -ldl -lm -o build/libcontensou_mujoco.so
echo "mujoco: build/libcontensou_mujoco.so"
if nm -D --defined-only build/libcontensou_mujoco.so | awk '$2 ~ /[TDB]/ { print $3 }' | grep -v '^_' | grep .; then
    echo "mujoco: the plugin exports symbols (above); it should export none" >&2
    exit 1
fi
gcc "${flags[@]}" examples/run_model.c "$lib" -Wl,-rpath,"$pkg" -lm -o build/run_model
echo "mujoco: build/run_model"
# The tests' shim (tests/inverse_mass_shim.c): the contacts' W through ctypes, no plugin registration.
gcc "${flags[@]}" -fvisibility=hidden -shared tests/inverse_mass_shim.c src/pairs.c src/inverse_mass.c src/step_aware.c \
    "$capi" "$lib" -Wl,--exclude-libs,ALL -Wl,-z,defs -Wl,-rpath,"$pkg" -lpthread -ldl -lm \
    -o build/libcontensou_mujoco_test.so
echo "mujoco: build/libcontensou_mujoco_test.so (tests only)"

if ((check)); then
    echo "mujoco: the four models from C under ASan + UBSan (plugin and runner instrumented), and a refused model"
    san=(-fsanitize=address,undefined -fno-sanitize-recover=all -g -O1)
    gcc -std=c11 -fPIC -ffp-contract=off "${san[@]}" -I"$(dirname "$headers")" -I../capi/include -shared \
        src/*.c "$capi" "$lib" -Wl,--exclude-libs,ALL -Wl,-rpath,"$pkg" -lpthread -ldl -lm \
        -o build/libcontensou_mujoco-san.so
    gcc -std=c11 "${san[@]}" -I"$(dirname "$headers")" examples/run_model.c "$lib" -Wl,-rpath,"$pkg" -lm -o build/run_model-san
    for model in tippe_top ball rattleback rattleback_rolling; do
        build/run_model-san build/libcontensou_mujoco-san.so "models/$model.xml" 0.02 >/dev/null
    done
    bad="$(mktemp -d)"
    sed 's/key="law" value="best"/key="law" value="stribeck"/' models/ball.xml >"$bad/ball.xml"
    if build/run_model-san build/libcontensou_mujoco-san.so "$bad/ball.xml" 0.01 >"$bad/out" 2>&1; then
        echo "mujoco: a model with law = stribeck was accepted" >&2
        exit 1
    fi
    grep -q "contensou.contact: law = 'stribeck' is no law" "$bad/out" ||
        { cat "$bad/out" >&2; echo "mujoco: the refusal does not name the attribute and value" >&2; exit 1; }
    rm -rf "$bad"
fi
