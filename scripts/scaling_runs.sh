#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# Strong and weak scaling runs of issue 43 item 4, for a machine with many cores and no Python (the lent 16-core
# machine inside ../shared/devkit's root; run from the directory that holds petmpm and inputs/). Each run's report
# becomes one line of JSONL in RESULTS; scripts/scaling.py --from RESULTS turns them into the tables of
# docs/performance.md.
#
#   strong3d  the 3D copper bar of inputs/bar_impact_3d.opts at 84 x 84 x 364 cells: 1,053,696 points
#   weak3d    bench.py's bar1 per rank (36 x 36 x 156 cells, 82,944 points), the box and the bar stretched along z
#   strong2d  the 2D bar of inputs/bar_impact_2d.opts at 600 x 2600 cells: 960,000 points
#   solo3d    weak3d's one-rank bar run as RANKS independent one-rank jobs at once (no communication): what sharing
#             the machine (memory bandwidth, the all-core clock) costs, apart from the exchanges. One line per copy
#             ("copy": i); scaling.py sums the copies' rates. Copy i runs on the i-th CPU the script may use: taskset
#             where it is found (on PATH or ./taskset) and there are as many CPUs as copies, else mpiexec --cpu-set i
#             --bind-to core where the machine binds.
# RESULTS.binding gets each rank's allowed CPUs (/proc/self/status) under the runs' mpiexec binding, and a taskset
# copy's under mpiexec --bind-to none.
# each in linear MUSL ("lin", the scene's own method) and in the program's default method ("def",
# inputs/methods/cpdi1.opts), on every rank count of RANKS, REPEAT times interleaved (repeat-major, so that a drift of
# the machine's speed touches every rank count alike), after one -log_view run of each method on 1 rank and on the
# largest count (LOGVIEW=0 or empty: none).
# Runs stop being started once BUDGET seconds have passed (what is done is kept).
#
# METHODS="def defw lin" adds the default method with -mpm_balance_weight work ("defw").
# usage: [CASES="strong3d weak3d strong2d solo3d"] [METHODS="def lin"] [LOGVIEW=1] scripts/scaling_runs.sh RESULTS
#        ["RANKS" (default "1 2 4 8 16")] [REPEAT (3)] [STEPS (20)] [BUDGET seconds (480)]
# (positional after RESULTS; LOGVIEW=0 or empty skips the -log_view runs)
# On the lent machine (../shared/devkit/README.md): pack with this script as an extra file, bind $OUT into the root
# and run it there, e.g. bash .devkit/run.sh bash scaling_runs.sh /out/runs.jsonl
set -u
res=${1:?usage: scripts/scaling_runs.sh RESULTS [RANKS] [REPEAT] [STEPS] [BUDGET]}
ranks=${2:-1 2 4 8 16}
repeat=${3:-3}
steps=${4:-20}
budget=${5:-480}
exe=./petmpm
t0=$(date +%s)
bind="--map-by core --bind-to core"
mpiexec -n "${ranks##* }" $bind $exe -help > /dev/null 2>&1 || bind="--bind-to none --oversubscribe" # every count binds, or none
{
  echo "{\"machine\": {\"cores\": $(nproc), \"cpu\": \"$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')\", \"bind\": \"$bind\"}}"
} >> "$res"
tmp=$(mktemp -d)
# Where the ranks may run: each rank's allowed CPUs as the kernel sees them (Cpus_allowed_list), at the largest count.
# solo3d pins copy i to the i-th CPU this script may use (cpus) with taskset where it exists (./taskset beside petmpm
# in ../shared/devkit's root) and there are enough of them; else the copies go unpinned (--bind-to none).
taskset=$(command -v taskset || { [[ -x ./taskset ]] && echo ./taskset; } || true)
cpus=()
for r in $(sed -n 's/^Cpus_allowed_list:[[:space:]]*//p' /proc/self/status | tr ',' ' '); do
  if [[ $r == *-* ]]; then for ((c = ${r%-*}; c <= ${r#*-}; c++)); do cpus+=("$c"); done; else cpus+=("$r"); fi
done
mpiexec -n "${ranks##* }" $bind bash -c 'echo "rank ${OMPI_COMM_WORLD_RANK:-?}: $(grep Cpus_allowed_list /proc/self/status)"' > "$res.binding" 2>&1
[[ -n $taskset ]] && echo "taskset -c ${cpus[0]} then mpiexec --bind-to none: $("$taskset" -c "${cpus[0]}" mpiexec -n 1 --bind-to none grep Cpus_allowed_list /proc/self/status 2>&1)" >> "$res.binding"

record() { # record REPORT LOG KEYS EXTRA: append {KEYS, EXTRA"report": REPORT} to RESULTS, or {KEYS, "failed": true} and LOG's tail
  if [[ -s $1 ]]; then
    printf '{%s, %s"report": %s}\n' "$3" "$4" "$(tr -d '\n' < "$1")" >> "$res"
  else
    printf '{%s, "failed": true}\n' "$3" >> "$res"
    tail -5 "$2"
  fi
}

one() { # one CASE METHOD RANKS REP [LOGVIEW]: run and append {"case", "method", "ranks", "rep", "seconds", "report"}
  local c=$1 m=$2 r=$3 k=$4 lv=${5:-} args=() s e
  case $c in
    strong3d) args=(-options_file inputs/bar_impact_3d.opts -mpm_cells 84,84,364) ;;
    weak3d) args=(-options_file inputs/bar_impact_3d.opts -mpm_cells 36,36,$((156 * r)) -mpm_hi 0.6,0.6,$((26 * r / 10)).$((26 * r % 10))
      -region_bar_hi 0.4,0.4,$((24 * r / 10)).$((24 * r % 10))) ;;
    strong2d) args=(-options_file inputs/bar_impact_2d.opts -mpm_cells 600,2600) ;;
    solo3d) solo "$@"; return ;;
    *) echo "scaling_runs.sh: unknown case $c (strong3d, weak3d, strong2d, solo3d)" >&2; return 1 ;;
  esac
  [[ $m == def* ]] && args+=(-options_file inputs/methods/cpdi1.opts)
  [[ $m == defw ]] && args+=(-mpm_balance_weight work)
  [[ -n $lv ]] && args+=(-log_view)
  rm -rf "$tmp/o" "$tmp/r.json"
  s=$(date +%s%N)
  mpiexec -n "$r" $bind $exe "${args[@]}" -ts_max_steps "$steps" -mpm_progress 0 -mpm_output "$tmp/o" \
    -mpm_report "$tmp/r.json" > "$tmp/log" 2>&1
  e=$(date +%s%N)
  record "$tmp/r.json" "$tmp/log" "$(printf '"case": "%s", "method": "%s", "ranks": %s, "rep": %s' "$c" "$m" "$r" "$k")" \
    "$(printf '"log_view": %s, "seconds": %s, ' "$([[ -n $lv ]] && echo true || echo false)" "$(( (e - s) / 1000000000 )).$(printf %03d $(( (e - s) / 1000000 % 1000 )))")"
  [[ -n $lv ]] && { echo "== log_view $c $m $r"; sed -n '/Summary of Stages/,$p' "$tmp/log"; } >> "$res.log_view"
  echo "$c $m $r rep $k: $(( $(date +%s) - t0 )) s"
}

solo() { # solo CASE METHOD COPIES REP: COPIES one-rank runs of weak3d's bar at once, one line each
  local c=$1 m=$2 n=$3 k=$4 i args=(-options_file inputs/bar_impact_3d.opts -mpm_cells 36,36,156) b=(--bind-to none)
  [[ $m == def* ]] && args+=(-options_file inputs/methods/cpdi1.opts)
  for ((i = 0; i < n; i++)); do
    rm -rf "$tmp/o$i" "$tmp/r$i.json"
    pin=()
    if ((n <= ${#cpus[@]})); then # a CPU each; else unpinned
      if [[ -n $taskset ]]; then pin=("$taskset" -c "${cpus[i]}"); elif [[ $bind == *core* ]]; then b=(--cpu-set "${cpus[i]}" --bind-to core); fi
    fi
    ${pin[@]+"${pin[@]}"} mpiexec -n 1 "${b[@]}" $exe "${args[@]}" -ts_max_steps "$steps" -mpm_progress 0 -mpm_output "$tmp/o$i" \
      -mpm_report "$tmp/r$i.json" > "$tmp/log$i" 2>&1 &
  done
  wait
  for ((i = 0; i < n; i++)); do
    record "$tmp/r$i.json" "$tmp/log$i" "$(printf '"case": "%s", "method": "%s", "ranks": %s, "rep": %s, "copy": %s' "$c" "$m" "$n" "$k" "$i")" ""
  done
  echo "$c $m $n copies rep $k: $(( $(date +%s) - t0 )) s"
}

late() { (( $(date +%s) - t0 > budget )); }
last=${ranks##* }
[[ ${LOGVIEW-1} && ${LOGVIEW-1} != 0 ]] && for r in 1 "$last"; do for m in def lin; do late || one strong3d $m "$r" 0 logview; done; done
for c in ${CASES:-strong3d weak3d strong2d}; do
  for k in $(seq "$repeat"); do
    for r in $ranks; do
      for m in ${METHODS:-def lin}; do
        late && break 4
        one $c $m "$r" "$k"
      done
    done
  done
done
rm -rf "$tmp"
echo "done in $(( $(date +%s) - t0 )) s"
