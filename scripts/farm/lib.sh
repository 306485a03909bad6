# Sourced by scripts/farm/shot.sh and sweep.sh: what submitting to Slurm and waiting on it share.

# A job's states (an array job's, each once): scontrol while the controller keeps the job, else
# sacct where the cluster keeps accounting.
farm_state() {
  local s
  s=$(scontrol show job "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | cut -d= -f2 | sort -u | tr '\n' ' ')
  [ -n "$s" ] || s=$(sacct -n -X -j "$1" -o State 2>/dev/null | awk '{print $1}' | sort -u | tr '\n' ' ')
  echo "${s:-UNKNOWN}"
}

# farm_wait TIMEOUT LOGDIR NAME=ID... : reports each change of the jobs' states until the last job
# has completed (0) or one has failed for good (1: a failed task may still be requeued, so a
# failure is final once the last job has ended or the first has failed), or TIMEOUT seconds (1).
farm_wait() {
  local timeout=$1 logs=$2
  shift 2
  local jobs=("$@") first=${1#*=} last=${!#} now previous="" start=$SECONDS j
  last=${last#*=}
  while :; do
    now=""
    for j in "${jobs[@]}"; do now+="${j%%=*}: $(farm_state "${j#*=}")"; done
    [ "$now" = "$previous" ] || echo "farm: $now"
    previous=$now
    if [[ "$now" =~ FAILED|CANCELLED|TIMEOUT|NODE_FAIL|OUT_OF_MEMORY|DEADLINE ]]; then
      if [[ "$(farm_state "$last")" =~ COMPLETED|FAILED|CANCELLED|TIMEOUT ]] ||
         [[ "$(farm_state "$first")" =~ FAILED|CANCELLED|TIMEOUT ]]; then
        echo "farm: a job failed; the logs are in $logs/" >&2
        return 1
      fi
    fi
    [ "$(farm_state "$last")" != "COMPLETED " ] || return 0
    if [ $((SECONDS - start)) -ge "$timeout" ]; then
      echo "farm: gave up waiting after $timeout s" >&2
      return 1
    fi
    sleep 1
  done
}
