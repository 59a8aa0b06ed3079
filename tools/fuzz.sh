#!/usr/bin/env bash
# Fuzzing (issue 8): runs every cargo-fuzz target of fuzz/ for SECONDS each (default 10, one
# process each, sequentially) and prints a markdown table of executions, libFuzzer coverage
# (cov: edges, ft: features), corpus size and findings. Any crash fails the script (the
# libFuzzer log of the failing target is printed). Needs the nightly toolchain; installs
# cargo-fuzz if missing (≈35 s from crates.io).
#   tools/fuzz.sh            # CI smoke run, 10 s per target
#   tools/fuzz.sh 150        # the recorded run (bench-results/fuzz.md)
set -euo pipefail
cd "$(dirname "$0")/.."
secs="${1:-10}"
targets=(elliptic geometry normal friction wrench rolling rolling_wrench jacobian step)
command -v cargo-fuzz >/dev/null || cargo install cargo-fuzz --locked
logs=fuzz/target/logs
mkdir -p "$logs"
cargo +nightly fuzz build -O >"$logs/build.log" 2>&1 || { cat "$logs/build.log" >&2; exit 1; }
echo "| target | seconds | executions | exec/s | cov | ft | corpus | crashes |"
echo "|---|---|---|---|---|---|---|---|"
failed=0
for t in "${targets[@]}"; do
    log="$logs/$t.log"
    rc=0
    cargo +nightly fuzz run -O "$t" -- -max_total_time="$secs" -print_final_stats=1 >"$log" 2>&1 || rc=$?
    stat() { grep -m1 "^stat::$1:" "$log" | awk '{print $2}'; }
    last="$(grep -E '^#[0-9]+' "$log" | tail -n 1)"
    cov="$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")"
    ft="$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")"
    corp="$(sed -n 's/.* corp: \([0-9]*\).*/\1/p' <<<"$last")"
    crashes=0
    if ((rc != 0)); then
        crashes=1
        failed=1
    fi
    echo "| $t | $secs | $(stat number_of_executed_units) | $(stat average_exec_per_sec) | $cov | $ft | $corp | $crashes |"
done
if ((failed)); then
    for t in "${targets[@]}"; do
        if grep -q -E 'panicked|deadly signal|ERROR: libFuzzer' "$logs/$t.log"; then
            echo "FUZZ FINDING in target $t:" >&2
            grep -E -A3 'panicked|SUMMARY|Test unit written' "$logs/$t.log" >&2
        fi
    done
    exit 1
fi
