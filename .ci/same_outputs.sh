#!/usr/bin/env bash
# Compares every output of two builds of `model` (a move of code must change none): the
# standard output of analyze (text and JSON), continue (JSON and CSV), clear (JSON and every
# file of its --out folder) and report (every file), on the aircraft A, B and the fighter and
# the shipped boxes. Only the proof's wall-clock seconds in the clearance's summary.md are
# masked. Usage: .ci/same_outputs.sh OLD_BINARY NEW_BINARY
set -euo pipefail
old=$(realpath "$1")
new=$(realpath "$2")
root="$(cd "$(dirname "$0")/.." && pwd)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() {
    local bin=$1 out=$2
    mkdir -p "$out"
    cd "$out"
    for ac in A B "$root/aircraft/fighter.toml"; do
        local tag
        tag=$(basename "$ac" .toml)
        "$bin" analyze "$ac" > "analyze-$tag.txt"
        "$bin" analyze "$ac" --json > "analyze-$tag.json"
        "$bin" continue "$ac" --json --csv "continue-$tag.csv" > "continue-$tag.json"
        "$bin" report "$ac" --out "report-$tag" > "report-$tag.txt"
    done
    for box in a_uncertain fighter_uncertain; do
        "$bin" clear "$root/aircraft/$box.toml" --json --out "clear-$box" > "clear-$box.json"
    done
    sed -i -E 's/ slabs, [0-9.]+ s;/ slabs, (seconds) s;/' clear-*/summary.md
}
run "$old" "$work/old"
run "$new" "$work/new"
if diff -r "$work/old" "$work/new" > "$work/diff"; then
    echo "same outputs: $(find "$work/new" -type f | wc -l) files"
else
    head -40 "$work/diff"
    exit 1
fi
