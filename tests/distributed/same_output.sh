#!/usr/bin/env bash
# `sample --distributed` as a user runs it, under mpirun: the merged output on 1, 2 and 3 ranks
# is byte for byte the output of `sample --decompose on` with the same seed, on a torus, under a
# mask and with an intensity map; the parts, joined in order, are the same rows; what it cannot
# do is refused with exit 2.
# Usage: same_output.sh SHAPEPROC MPIRUN DATA_DIR
set -euo pipefail
shapeproc=$1
mpirun=$2
data=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
run() { "$mpirun" --oversubscribe --noprefix --bind-to none -n "$@"; }
fail() { echo "FAIL: $*" >&2; exit 1; }

"$shapeproc" fit "$data/svg/dots-random.svg" -o model.json -q > /dev/null
for domain in "" "--domain $data/maps/star.svg" "--intensity $data/maps/gradient.png"; do
  # shellcheck disable=SC2086  # the mask's and the map's two words
  "$shapeproc" sample model.json --size 2400,2400 $domain --decompose on --seed 5 -o one.csv -q \
    --force > /dev/null
  [ "$(wc -l < one.csv)" -gt 1000 ] || fail "${domain:-(torus)}: too few elements to tell"
  for ranks in 1 2 3; do
    # shellcheck disable=SC2086
    run "$ranks" "$shapeproc" sample model.json --size 2400,2400 $domain --distributed --merge --force \
      --seed 5 -o "merged-$ranks.csv" -q > "log-$ranks.txt"
    cmp one.csv "merged-$ranks.csv" || fail "$ranks rank(s) ${domain:-(torus)}: not the one-process output"
    grep -q "across $ranks rank(s)" "log-$ranks.txt" || fail "rank 0 does not report the ranks"
    [ "$(grep -c '^sampled' "log-$ranks.txt")" = 1 ] || fail "ranks other than 0 printed"
  done
done

# Parts and their manifest: the parts' rows, in order, are the merged rows.
run 3 "$shapeproc" sample model.json --size 2400,2400 --distributed --seed 5 -o parts.csv -q \
  > /dev/null
for k in 1 2 3; do [ -s "parts-part-$k-of-3.csv" ] || fail "part $k missing"; done
grep -q '"elements"' parts.parts.json || fail "no manifest"
{ head -n 1 parts-part-1-of-3.csv; for k in 1 2 3; do tail -n +2 "parts-part-$k-of-3.csv"; done; } \
  > joined.csv
"$shapeproc" sample model.json --size 2400,2400 --decompose on --seed 5 -o torus.csv -q > /dev/null
cmp torus.csv joined.csv || fail "the parts joined are not the one-process output"

# Refusals, each with exit 2 and nothing written.
refused() {
  local status=0
  "$@" > out.txt 2> err.txt || status=$?
  [ "$status" = 2 ] || fail "exit $status, not 2, for: $*"
  [ -s err.txt ] || fail "no message for: $*"
}
refused "$shapeproc" sample model.json --size 2400,2400 --distributed -o out.svg
refused "$shapeproc" sample model.json --size 2400,2400 --distributed -o out.csv --png out.png
refused "$shapeproc" sample model.json --size 2400,2400 --merge -o out.csv
refused run 3 "$shapeproc" sample model.json --size 2400,2400 --distributed -o parts.csv
grep -q "exists" err.txt || fail "an existing part was not named"
# A merge would write (then remove) the parts of that run: refused as well.
refused run 3 "$shapeproc" sample model.json --size 2400,2400 --distributed --merge -o parts.csv
grep -q "parts-part-1-of-3.csv exists" err.txt || fail "a merge over existing parts: $(cat err.txt)"
# 5 ranks, 4 rows of cells.
refused run 5 "$shapeproc" sample model.json --size 320,320 --distributed -o small.csv
grep -q "rows of cells" err.txt || fail "too many ranks: $(cat err.txt)"
[ ! -e small.parts.json ] && [ ! -e out.svg ] && [ ! -e out.csv ] || fail "a refused run wrote"
echo "same output on 1, 2 and 3 ranks; refusals ok"
