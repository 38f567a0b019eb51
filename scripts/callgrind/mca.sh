#!/usr/bin/env bash
# Machine code of the hooks in src/bin/hooks.rs under llvm-mca: per function, its instructions up to
# the first `ret` (the path taken when q̈ is finite; calls, jumps and the frame left out, RIP-relative
# loads read from a register) and the cycles of one pass through them (-iterations=1: the latency of
# the longest chain, the loads included). Needs llvm-mca and objdump. CPU=znver3 by default.
set -euo pipefail
cd "$(dirname "$0")"
cargo build --release --quiet --bin hooks
bin=${CARGO_TARGET_DIR:-target}/release/hooks
out=$(mktemp -d)
for f in ${FUNCTIONS:-kepler hw_kepler fpu hw_fpu}; do
  objdump -d --no-show-raw-insn -C --disassemble="hooks::$f" "$bin" | grep -E '^\s+[0-9a-f]+:' |
    sed -E 's/^\s+[0-9a-f]+:\s+//; s/#.*$//' | awk '/^ret/{exit} {print}' |
    grep -vE '^(j[a-z]+|push|pop|sub +\$|add +\$|call)' |
    sed -E 's/-?0x[0-9a-f]+\(%rip\)/(%rax)/g' > "$out/$f.s"
  cycles=$(llvm-mca -mcpu="${CPU:-znver3}" -iterations=1 "$out/$f.s" 2>/dev/null | awk '/Total Cycles/{print $3}')
  echo "$f $(wc -l < "$out/$f.s") instructions, $cycles cycles"
done
rm -r "$out"
