#!/usr/bin/env bash
# The C twin (examples/wrench_eval.c, linked to the host staticlib) against the Rust contract
# (`contact_eval wrench`, and with `jacobian` `contact_eval jacobian`), bit for bit: the same rows (examples/bits.rs `gen`: every patch
# shape, damping/friction/slip regime, contact loss, valid extremes) through every law × form
# × precision; every field of both outputs is parsed in the run's precision and must have the
# same bits. Then the error paths (`bits bad`): both stop at the same row with exit 1 and print
# the same rows before it. Usage: capi/tests/compare.sh (after capi/build.sh, or it builds).
set -euo pipefail
cd "$(dirname "$0")/.."
[[ -x target/release/wrench_eval && -x target/release/wrench_eval-san && -x target/release/rolling_eval &&
   -x target/release/step_eval && -x target/release/step_eval-san ]] || ./build.sh --no-check
cargo build --release --quiet --example bits
bits=target/release/examples/bits
c=target/release/wrench_eval

# The reference: the CLI's `wrench` subcommand (src/bin/contact_eval).
(cd .. && cargo build --release --quiet --bin contact_eval)
ref=(../target/release/contact_eval wrench)
header="P,Q,estar,cd,f,delta,h,hdot,vx,vy,omega"

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# The twin under test and its reference, as commands (set before each section).
twin=("$c")

# same FILE ROWS PRECISION OPTS...: "${twin[@]}" and "${ref[@]}" on $work/FILE.csv with OPTS
# both succeed with ROWS rows, every field of both outputs with the same bits in PRECISION.
same() {
    local file="$1" want="$2" precision="$3" n
    shift 3
    "${twin[@]}" "$@" <"$work/$file.csv" >"$work/c.csv" || { echo "compare: ${twin[*]} failed for $file $*" >&2; exit 1; }
    "${ref[@]}" "$@" <"$work/$file.csv" >"$work/rust.csv" || { echo "compare: ${ref[*]} failed for $file $*" >&2; exit 1; }
    n="$("$bits" check "$precision" "$work/c.csv" "$work/rust.csv")" || { echo "compare: FAILED: ${twin[*]} on $file $*" >&2; exit 1; }
    ((n == want)) || { echo "compare: $n of $want rows: ${twin[*]} on $file $*" >&2; exit 1; }
}

# sweep ROWS FIRST_LAWS OTHER_LAWS FILE...: `same` on every FILE (ROWS rows) × precision × form
# × law — the first FILE through FIRST_LAWS, the others through OTHER_LAWS; the runs add to
# $runs.
sweep() {
    local want="$1" first="$2" other="$3" file precision form law laws
    shift 3
    for file in "$@"; do
        read -ra laws <<<"$other"
        [[ "$file" == "$1" ]] && read -ra laws <<<"$first"
        for precision in f32 f64; do
            for form in fixed varying; do
                for law in "${laws[@]}"; do
                    same "$file" "$want" "$precision" --law "$law" --form "$form" --precision "$precision"
                    runs=$((runs + 1))
                done
            done
        done
    done
}
all_laws="best simplified pade ellipsoid coulomb table blend fastsim fastsim-16"

# clean FILE OPTS...: the twin built with ASan + UBSan (build.sh: NAME-san) runs clean on
# $work/FILE.csv with OPTS and --precision f32, then f64, and prints what the plain twin prints.
clean() {
    local file="$1" precision
    shift
    for precision in f32 f64; do
        "${twin[0]}-san" "${twin[@]:1}" "$@" --precision "$precision" <"$work/$file.csv" >"$work/san.csv" ||
            { echo "compare: the sanitized ${twin[*]} failed on $file $* ($precision)" >&2; exit 1; }
        "${twin[@]}" "$@" --precision "$precision" <"$work/$file.csv" | cmp -s - "$work/san.csv" ||
            { echo "compare: the sanitized ${twin[*]} prints other values on $file $* ($precision)" >&2; exit 1; }
    done
}

# refused OPTS...: the twin and the reference on $work/in.csv (a bad row in it): their exit
# codes rc_c, rc_r and messages msg_c, msg_r — the same text expected, but for the program's
# name, the C twin's status code and the value (the C twin echoes the field, the CLI its
# shortest float).
refused() {
    set +e
    "${twin[@]}" "$@" <"$work/in.csv" >"$work/c.csv" 2>"$work/c.err"; rc_c=$?
    "${ref[@]}" "$@" <"$work/in.csv" >"$work/rust.csv" 2>"$work/rust.err"; rc_r=$?
    set -e
    msg_c="$(sed -e "s/^$(basename "${twin[0]}"): //" -e 's/ (status [0-9]*)$//' -e 's/ = [^:]*:/ = _:/' "$work/c.err")"
    msg_r="$(sed -e 's/^contact_eval: //' -e 's/ = [^:]*:/ = _:/' "$work/rust.err")"
}

# stopped_alike ROW WHAT PRECISION: after `refused`, both exited 1 with the same message at
# row ROW and wrote the same rows before it (parsed in PRECISION); else a report on WHAT.
stopped_alike() {
    if ((rc_c != 1 || rc_r != 1)) || [[ "$msg_c" != "$msg_r" || "$msg_c" != "row $1: "* ]]; then
        printf 'compare: %s (%s): exit %s / %s, expected 1 at row %s with the same message\n  C:    %s\n  Rust: %s\n' \
            "$2" "$3" "$rc_c" "$rc_r" "$1" "$msg_c" "$msg_r" >&2
        exit 1
    fi
    "$bits" check "$3" "$work/c.csv" "$work/rust.csv" >/dev/null
}

# bad_kinds HEADER CHECK: for each kind of bad row in $work/bad.tsv (`bits *-bad`),
# $work/in.csv = HEADER then that kind's rows, and `CHECK KIND`; $kinds counts them.
bad_kinds() {
    local kind
    kinds=0
    for kind in $(cut -f1 "$work/bad.tsv" | uniq); do
        { echo "$1"; grep "^$kind"$'\t' "$work/bad.tsv" | cut -f2-; } >"$work/in.csv"
        "$2" "$kind"
        kinds=$((kinds + 1))
    done
}
"$bits" gen >"$work/rows.csv"
rows=$(($(wc -l <"$work/rows.csv") - 1))
runs=0
sweep "$rows" "$all_laws" "" rows
echo "compare: $rows rows × $runs runs (9 laws × 2 forms × 2 precisions): C = Rust bit for bit"

# The optional rolling columns (G, nu, vrx, vry): all four, vrx/vry only (G, nu
# by default), and two in another order, through the rolling laws (and best, which ignores
# them), every form and precision.
"$bits" wrench-rolling-gen >"$work/roll4.csv"
cut -d, -f1-11,14,15 "$work/roll4.csv" >"$work/roll2.csv"
awk -F, -v OFS=, '{ s = $1; for (k = 2; k <= 11; k++) s = s OFS $k; print s, $15, $13 }' "$work/roll4.csv" >"$work/rollswap.csv"
rrows=$(($(wc -l <"$work/roll4.csv") - 1))
runs=0
sweep "$rrows" "table blend fastsim fastsim-16 best" table roll4 roll2 rollswap
clean roll4 --law table --form varying
echo "compare: rolling columns: $rrows rows × $runs runs (G,nu,vrx,vry: 5 laws; vrx,vry and vry,nu: table; 2 forms × 2 precisions): C = Rust bit for bit; ASan + UBSan clean (table)"

# The C side under AddressSanitizer + UndefinedBehaviorSanitizer (built by build.sh): clean
# on every row, and the same output.
for form in fixed varying; do
    clean rows --law best --form "$form"
done
echo "compare: the C twin is clean under ASan + UBSan (best, both forms and precisions)"

# The Jacobian (contensou_contact_jacobian_*, _jacobian_rolling_*): `wrench_eval jacobian`
# against `contact_eval jacobian` on the same rows, every field (N, Fx, Fy, Tz and the 20
# derivatives) bit for bit.
twin=("$c" jacobian)
ref=(../target/release/contact_eval jacobian)
runs=0
sweep "$rows" "$all_laws" "" rows
sweep "$rrows" "table blend fastsim fastsim-16 best" table roll4 roll2
clean roll4 --law table --form varying
echo "compare: jacobian: $rows rows (9 laws) and $rrows rolling rows (G,nu,vrx,vry: 5 laws; vrx,vry: table) × 2 forms × 2 precisions, $runs runs: C = contact_eval jacobian bit for bit; ASan + UBSan clean (table)"

# wrench_bad KIND: the bad rows through `wrench` and `jacobian` in both precisions.
wrench_bad() {
    local precision
    for precision in f32 f64 jacobian-f32 jacobian-f64; do
        # jacobian-*: `wrench_eval jacobian` against `contact_eval jacobian`
        twin=("$c"); ref=(../target/release/contact_eval wrench)
        if [[ "$precision" == jacobian-* ]]; then
            precision="${precision#jacobian-}"; twin=("$c" jacobian); ref=(../target/release/contact_eval jacobian)
        fi
        refused --law best --form varying --precision "$precision"
        stopped_alike 4 "bad row '$1'" "$precision"
        grep -q ' (status [0-9]*)$' "$work/c.err" || [[ "$1" =~ ^(nan|text|empty|fields)$ ]] ||
            { echo "compare: C message of '$1' has no status code: $(cat "$work/c.err")" >&2; exit 1; }
    done
}
"$bits" bad >"$work/bad.tsv"
bad_kinds "$header" wrench_bad
echo "compare: $kinds kinds of bad row (wrench and jacobian): both stop at row 4 with the same message, exit 1, same rows before it"

# Bad rolling columns (law table): the same row, column and message from both.
twin=("$c"); ref=(../target/release/contact_eval wrench)
good="50,50,1.15e11,0,0.1,1e-4,1e-6,0,0.01,0,50,8e10,0.28,2,0"
for bad in "50,50,1.15e11,0,0.1,1e-4,1e-6,0,0.01,0,50,-8e10,0.28,2,0" \
    "50,50,1.15e11,0,0.1,1e-4,1e-6,0,0.01,0,50,8e10,0.6,2,0" \
    "50,50,1.15e11,0,0.1,1e-4,1e-6,0,0.01,0,50,inf,0.28,2,0" \
    "50,50,1.15e11,0,0.1,1e-4,1e-6,0,0.01,0,50,8e10,0.28,inf,0" \
    "50,50,1.15e11,0,0.1,1e-4,1e-6,0,0.01,0,50,8e10,0.28,2,-inf"; do
    printf '%s\n' "${header},G,nu,vrx,vry" "$good" "$good" "$bad" "$good" >"$work/in.csv"
    for precision in f32 f64; do
        refused --law table --form fixed --precision "$precision"
        stopped_alike 3 "bad rolling column $bad" "$precision"
    done
done
echo "compare: 5 bad rolling-column rows (G, nu, vrx, vry): both stop at row 3 with the same message"

# The rolling evaluator (examples/rolling_eval.c) against `contact_eval rolling`:
# every rolling law × precision, bit for bit; clean under ASan + UBSan; the same bad rows
# stop both at the same row.
"$bits" rolling-gen >"$work/rolling.csv"
rows=$(($(wc -l <"$work/rolling.csv") - 1))
twin=(target/release/rolling_eval); ref=(../target/release/contact_eval rolling)
runs=0
for precision in f32 f64; do
    for law in table blend fastsim fastsim-16 full-slip linear; do
        same rolling "$rows" "$precision" --law "$law" --precision "$precision"
        runs=$((runs + 1))
    done
done
clean rolling --law table
echo "compare: rolling: $rows rows × $runs runs (6 laws × 2 precisions): C = contact_eval rolling bit for bit; clean under ASan + UBSan (table)"

# rolling_bad KIND: the same row and column from both (contact_eval names a non-finite input
# in its message, the creepages by their slip: "row 4: xi = 1e-3: omega must be finite" for
# φ = ∞).
rolling_bad() {
    local precision col_c slip
    for precision in f32 f64; do
        refused --precision "$precision"
        col_c="$(sed -n 's/^rolling_eval: row 4: \([^ ]*\) = .*/\1/p' "$work/c.err")"
        case "$col_c" in xi) slip=v_x ;; eta) slip=v_y ;; phi) slip=omega ;; *) slip="$col_c" ;; esac
        if ((rc_c != 1 || rc_r != 1)) || [[ -z "$col_c" ]] ||
            ! grep -qE "^contact_eval: row 4: ($col_c = |.*: ($col_c|$slip) must be finite$)" "$work/rust.err"; then
            echo "compare: rolling bad row '$1' ($precision): C exit $rc_c, Rust exit $rc_r; expected exit 1 at row 4 naming the same column" >&2
            cat "$work/c.err" "$work/rust.err" >&2
            exit 1
        fi
        "$bits" check "$precision" "$work/c.csv" "$work/rust.csv" >/dev/null
    done
}
"$bits" rolling-bad >"$work/bad.tsv"
bad_kinds "a,b,G,nu,f,N,V,xi,eta,phi" rolling_bad
echo "compare: rolling: $kinds kinds of bad row: both stop at row 4 naming the same column, exit 1, same rows before it"

# The step-aware wrench (examples/step_eval.c, contensou_contact_step_*) against
# `contact_eval step`: every law × form × precision on rows with every optional column (G, nu,
# vrx, vry and the four free velocities), without the free columns (u_free NULL) and with two
# of them; bit for bit; clean under ASan + UBSan; the bad rows stop both at the same row with
# the same message.
"$bits" step-gen >"$work/step.csv"
cut -d, -f1-26 "$work/step.csv" >"$work/step-nofree.csv"
cut -d, -f1-22,28,30 "$work/step.csv" >"$work/step-some.csv"
srows=$(($(wc -l <"$work/step.csv") - 1))
twin=(target/release/step_eval); ref=(../target/release/contact_eval step)
runs=0
sweep "$srows" "$all_laws" "best table" step step-nofree step-some
clean step --law table --form varying
echo "compare: step: $srows rows × $runs runs (9 laws × 2 forms × 2 precisions with every optional column; best, table without and with two free columns): C = contact_eval step bit for bit; clean under ASan + UBSan (table)"

# step_bad KIND: the same row and message from both.
step_bad() {
    local precision
    for precision in f32 f64; do
        refused --precision "$precision"
        stopped_alike 4 "bad step row '$1'" "$precision"
    done
}
"$bits" step-bad >"$work/bad.tsv"
bad_kinds "$(head -n 1 "$work/step.csv" | cut -d, -f1-22)" step_bad
echo "compare: step: $kinds kinds of bad row (dt, W, start state): both stop at row 4 with the same message, exit 1, same rows before it"
