#!/usr/bin/env bash
# Throwaway single-node Slurm cluster (munged + slurmctld + slurmd) for tests.
#   bash slurm_cluster.sh start DIR   -> prints "export SLURM_CONF=DIR/slurm.conf"
#   bash slurm_cluster.sh stop DIR    -> kills only the daemons whose pid files are in DIR
# Everything (config, key, socket, state, logs, pid files) lives under DIR.
# Needs: slurm-wlm 22.05 + munge (apt), root. No systemd, no /etc changes.
set -euo pipefail

die() { echo "slurm_cluster: $*" >&2; exit 1; }
log() { echo "slurm_cluster: $*" >&2; }

[ $# -eq 2 ] || die "usage: $0 start|stop DIR"
CMD=$1
DIR=$(realpath -m "$2")
CONF=$DIR/slurm.conf
SOCK=$DIR/munge/munge.socket

# pid of daemon NAME from DIR/NAME.pid if that process is still alive and really
# is NAME (guards against a stale file whose pid was reused by something else).
live_pid() {
    local f=$DIR/$1.pid pid
    [ -s "$f" ] || return 1
    pid=$(tr -dc 0-9 <"$f")
    [ -n "$pid" ] && [ "$(cat "/proc/$pid/comm" 2>/dev/null)" = "$1" ] || return 1
    echo "$pid"
}

stop_one() {
    local pid
    pid=$(live_pid "$1") || { rm -f "$DIR/$1.pid"; return 0; }
    log "stopping $1 (pid $pid)"
    kill -TERM "$pid" 2>/dev/null || true
    for _ in $(seq 1 100); do                  # up to 20 s, then SIGKILL
        [ -d "/proc/$pid" ] || break
        sleep 0.2
    done
    if [ -d "/proc/$pid" ]; then kill -KILL "$pid" 2>/dev/null || true; fi
    rm -f "$DIR/$1.pid"
}

stop_cluster() {
    # Cancel our cluster's jobs first so no orphaned slurmstepd/job processes
    # survive slurmd (slurmstepd detaches from slurmd).
    if live_pid slurmctld >/dev/null; then
        SLURM_CONF=$CONF timeout 10 scancel --quiet --full --user=root 2>/dev/null || true
        for _ in $(seq 1 50); do
            [ -z "$(SLURM_CONF=$CONF timeout 5 squeue -h -o %i 2>/dev/null)" ] && break
            sleep 0.2
        done
    fi
    stop_one slurmd
    stop_one slurmctld
    stop_one munged
}

free_port() {  # first port >= $1 with no TCP listener
    local p=$1
    while ss -Hltn "sport = :$p" | grep -q .; do p=$((p + 1)); done
    echo "$p"
}

# Failed start: show the log tails, stop whatever did start (logs stay in DIR), exit 1.
fail() {
    for f in "$DIR"/log/*.log; do
        [ -f "$f" ] && { echo "==> $f <==" >&2; tail -n 20 "$f" >&2; }
    done
    stop_cluster
    die "$*"
}

start_cluster() {
    stop_cluster                           # leftovers of an earlier run in DIR
    mkdir -p "$DIR"/{munge,state,spool,log}
    chmod 755 "$DIR/munge"   # munged: socket dir must be o+x but not group/world-writable
    # Private munged: own key, socket, pid, seed and log; the system one is untouched.
    if [ ! -s "$DIR/munge/munge.key" ]; then
        mungekey --create --keyfile="$DIR/munge/munge.key" >&2
        chmod 400 "$DIR/munge/munge.key"
    fi
    munged --socket="$SOCK" --key-file="$DIR/munge/munge.key" \
        --pid-file="$DIR/munged.pid" --log-file="$DIR/log/munged.log" \
        --seed-file="$DIR/munge/munged.seed" \
        || fail "munged failed to start"

    local host ctl_port node_port
    host=$(hostname -s)
    ctl_port=$(free_port 6917)
    node_port=$(free_port $((ctl_port + 1)))
    # 127.0.0.1 addresses: no dependence on the hostname resolving in the container.
    # AuthInfo=socket= makes daemons AND client commands use the private munged.
    cat >"$CONF" <<EOF
ClusterName=edemtest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctl_port
SlurmdPort=$node_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$SOCK
StateSaveLocation=$DIR/state
SlurmdSpoolDir=$DIR/spool
SlurmctldPidFile=$DIR/slurmctld.pid
SlurmdPidFile=$DIR/slurmd.pid
SlurmctldLogFile=$DIR/log/slurmctld.log
SlurmdLogFile=$DIR/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MailProg=/bin/true
MinJobAge=60
NodeName=$host NodeAddr=127.0.0.1 NodeHostname=$host CPUs=$(nproc) RealMemory=1000 State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
    log "ports ctld=$ctl_port slurmd=$node_port, config $CONF"
    # -c: start with empty state (throwaway cluster); both daemons fork into background.
    slurmctld -c -f "$CONF" || fail "slurmctld failed to start"
    slurmd -f "$CONF" -N "$host" || fail "slurmd failed to start"

    local state=""
    for _ in $(seq 1 60); do
        state=$(SLURM_CONF=$CONF timeout 5 sinfo -h -n "$host" -o %t 2>/dev/null || true)
        [ "$state" = idle ] && break
        sleep 1
    done
    [ "$state" = idle ] || fail "node $host not idle after 60 s (state: '${state:-no answer}')"
    log "cluster up, node $host idle"
    echo "export SLURM_CONF=$CONF"
}

case $CMD in
    start) start_cluster ;;
    stop) stop_cluster ;;
    *) die "usage: $0 start|stop DIR" ;;
esac
