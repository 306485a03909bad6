#!/usr/bin/env bash
# A single-node Slurm on this machine, for the tests and for trying scripts/farm/shot.sh: munge,
# slurmctld and slurmd as root, no systemd, the configuration and all state in a folder of its
# own ($CSM_SLURM_DIR, default /tmp/csm-slurm).
#   bash scripts/farm/local_slurm.sh start    starts it (installs slurm-wlm and munge when they are
#                                            missing); prints the line that points Slurm's
#                                            commands at it: export SLURM_CONF=DIR/slurm.conf
#   bash scripts/farm/local_slurm.sh stop     stops it and removes the folder
#   bash scripts/farm/local_slurm.sh status   exits 0 when it is up (sinfo answers)
# Exit status 3 from start: Slurm cannot be installed or started here (said on stderr).
set -euo pipefail
dir=${CSM_SLURM_DIR:-/tmp/csm-slurm}
conf=$dir/slurm.conf
node=$(hostname -s)

install() {
  command -v slurmctld >/dev/null && command -v munged >/dev/null && return 0
  [ "$(id -u)" = 0 ] || { echo "local_slurm.sh: slurmctld is not installed and this is not root" >&2; return 1; }
  command -v apt-get >/dev/null || { echo "local_slurm.sh: no slurmctld and no apt-get" >&2; return 1; }
  apt-get update -qq >&2 || true
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq slurm-wlm munge >&2
}

up() {
  [ -f "$conf" ] && SLURM_CONF=$conf timeout 5 sinfo -h >/dev/null 2>&1
}

start() {
  if up; then
    echo "export SLURM_CONF=$conf"
    return 0
  fi
  install || exit 3
  mkdir -p "$dir"/{ctld,spool,log}
  # munge: the key Debian's package made, a socket of its own in /run/munge.
  mkdir -p /run/munge /var/log/munge /var/lib/munge
  chown munge:munge /run/munge /var/log/munge /var/lib/munge
  if [ ! -s /etc/munge/munge.key ]; then
    dd if=/dev/urandom of=/etc/munge/munge.key bs=1 count=1024 status=none
    chown munge:munge /etc/munge/munge.key
    chmod 400 /etc/munge/munge.key
  fi
  if ! pgrep -x munged >/dev/null; then
    runuser -u munge -- /usr/sbin/munged || { echo "local_slurm.sh: munged did not start" >&2; exit 3; }
  fi
  local cpus mem
  cpus=$(nproc)
  mem=$(( $(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 * 9 / 10 ))
  cat >"$conf" <<CONF
# Written by scripts/farm/local_slurm.sh: one node, this machine.
ClusterName=csmhair
SlurmctldHost=$node
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
SlurmctldPort=${CSM_SLURM_PORT:-6817}
SlurmdPort=$(( ${CSM_SLURM_PORT:-6817} + 1 ))
StateSaveLocation=$dir/ctld
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
JobRequeue=1
SlurmctldTimeout=30
SlurmdTimeout=30
InactiveLimit=0
KillWait=5
MinJobAge=600
NodeName=$node CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=local Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
  SLURM_CONF=$conf slurmctld -i || { echo "local_slurm.sh: slurmctld did not start (see $dir/log)" >&2; exit 3; }
  SLURM_CONF=$conf slurmd || { echo "local_slurm.sh: slurmd did not start (see $dir/log)" >&2; exit 3; }
  for _ in $(seq 100); do
    if SLURM_CONF=$conf sinfo -h -o %t 2>/dev/null | grep -qE '^(idle|mix|alloc)'; then
      echo "export SLURM_CONF=$conf"
      return 0
    fi
    sleep 0.2
  done
  echo "local_slurm.sh: the node did not come up (see $dir/log)" >&2
  exit 3
}

stop() {
  for daemon in slurmd slurmctld; do
    if [ -f "$dir/$daemon.pid" ]; then
      kill "$(cat "$dir/$daemon.pid")" 2>/dev/null || true
    fi
  done
  for _ in $(seq 50); do
    pgrep -f "slurm(ctld|d)" >/dev/null || break
    sleep 0.1
  done
  rm -rf "$dir"
}

case "${1:-}" in
  start) start ;;
  stop) stop ;;
  status) up ;;
  *) echo "usage: local_slurm.sh start|stop|status" >&2; exit 2 ;;
esac
