#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# Runs CMD… in a brand-new Debian 12 (bookworm) root file system, as a new user on a fresh
# machine would: the root is made for this one run (mmdebstrap --variant=apt, plus
# ca-certificates and git), the project's committed HEAD is cloned into /root/pgloss, and CMD
# runs there as root with an empty environment (PATH, HOME=/root, LANG=C.UTF-8, the cache's
# PGLOSS_WHEELHOUSE, and any NAME=VALUE given before CMD). Uncommitted changes are NOT
# included: commit first.
#
#   scripts/fresh-debian.sh bash scripts/test.sh
#   scripts/fresh-debian.sh PGLOSS_REQUIRE_ALL=1 bash scripts/test-tracer.sh
#
# What comes in from this machine: its network set-up only — the extra CA certificates in
# /usr/local/share/ca-certificates (update-ca-certificates runs inside), /etc/pip.conf (and
# any certificate file it names), /etc/resolv.conf (mmdebstrap copies it), and a localhost
# /etc/hosts as Debian's installer writes. Download caches (apt's .deb files, linked in and
# back out; pip's HTTP cache and the wheelhouse, bind-mounted, the latter named to the scripts
# by PGLOSS_WHEELHOUSE) live in PGLOSS_FRESH_CACHE (default /var/cache/pgloss-fresh; "none" for
# no cache): they save downloads but hold no installed package, venv, built wheel or build
# tree, so they cannot hide a missing install. (pip only caches responses with caching
# headers; an egress proxy that strips them leaves its HTTP cache empty, hence the wheelhouse.)
# The mounts (/proc, /sys, a private /dev with its own /dev/pts and /dev/shm, the caches)
# live in a private mount and PID namespace: nothing stays mounted and nothing keeps running
# when the run ends or is killed, and the root is deleted afterwards (PGLOSS_FRESH_KEEP=1
# keeps it for a look). The exit status is CMD's. Needs root, mmdebstrap and git on the host
# (.ci/run installs them through scripts/bootstrap.sh).
set -euo pipefail

log() { printf '[fresh-debian %(%H:%M:%S)T] %s\n' -1 "$*"; }
die() { log "ERROR: $*" >&2; exit 2; }

# ---------------------------------------------------------------------------------------
# Inside the namespaces (re-executed by the outer part below): build, populate, run.
if [[ ${1:-} == --inside ]]; then
  shift
  root=$1 repo=$2 commit=$3 cache=$4; shift 4
  stage_start=$SECONDS stage_times=()
  stage() { # NAME: closes the previous stage with its time, opens NAME
    if [[ -n ${stage_name:-} ]]; then
      log "stage '$stage_name' done in $((SECONDS - stage_start)) s"
      stage_times+=("$stage_name $((SECONDS - stage_start)) s")
    fi
    stage_name=$1 stage_start=$SECONDS
    [[ -n $1 ]] && log "stage '$1' ..."
    return 0
  }
  mount --make-rprivate /   # belt and braces: nothing below propagates back to the host

  stage "mmdebstrap"
  log "mmdebstrap --variant=apt --include=ca-certificates,git bookworm $root"
  # Without a mirror argument mmdebstrap uses deb.debian.org with bookworm, -updates and
  # -security, as a Debian 12 installation does. It copies the host's resolv.conf in.
  mmdebstrap --quiet --variant=apt --include=ca-certificates,git bookworm "$root"
  log "root: $(du -sh --one-file-system "$root" | cut -f1), $(chroot "$root" dpkg-query -W | wc -l) packages," \
    "Debian $(cat "$root/etc/debian_version")"

  stage "network set-up"
  # What Debian's installer writes on every machine (no package owns it): localhost resolves.
  [[ -e $root/etc/hosts ]] || printf '127.0.0.1\tlocalhost\n::1\t\tlocalhost ip6-localhost ip6-loopback\n' >"$root/etc/hosts"
  n=0
  for crt in /usr/local/share/ca-certificates/*.crt; do
    [[ -f $crt ]] || continue
    cp "$crt" "$root/usr/local/share/ca-certificates/"; n=$((n + 1))
  done
  chroot "$root" /usr/sbin/update-ca-certificates 2>&1 | { grep -v -e '^rehash: warning: skipping ca-certificates.crt' -e '^Updating' -e 'added, .* removed' -e '^Running hooks' -e '^done\.$' || true; }
  log "carried $n extra CA certificate(s) from /usr/local/share/ca-certificates"
  if [[ -f /etc/pip.conf ]]; then
    cp /etc/pip.conf "$root/etc/pip.conf"
    # pip.conf may name certificate files (cert = …, client-cert = …): they must exist inside.
    while read -r f; do
      [[ -n $f ]] || continue
      if [[ -e $root$f ]]; then
        log "pip.conf names $f: present in the root"
      elif [[ -f $f ]]; then
        mkdir -p "$(dirname "$root$f")"; cp "$f" "$root$f"; log "pip.conf names $f: copied in"
      else
        die "/etc/pip.conf names $f, which exists neither here nor in the root"
      fi
    done < <(sed -nE 's/^[[:space:]]*(cert|client-cert)[[:space:]]*[=:][[:space:]]*(.*[^[:space:]])[[:space:]]*$/\2/p' /etc/pip.conf)
    log "carried /etc/pip.conf ($(grep -cvE '^[[:space:]]*(#|;|$)' /etc/pip.conf) setting line(s))"
  fi

  stage "clone"
  git clone --quiet --no-hardlinks "$repo" "$root/root/pgloss"
  git -C "$root/root/pgloss" -c advice.detachedHead=false checkout --quiet --detach "$commit"
  log "cloned $repo at $(git -C "$root/root/pgloss" log -1 --format='%h %s')"

  stage "mounts"
  mount -t proc proc "$root/proc"          # this PID namespace's processes only
  mount -t sysfs -o ro sysfs "$root/sys"
  # A private /dev: only the usual character devices, a new devpts instance and an empty
  # /dev/shm (POSIX shared memory: Mesa's llvmpipe, Chromium, Python multiprocessing).
  mount -t tmpfs -o mode=755,nosuid tmpfs "$root/dev"
  for d in null zero full random urandom tty; do
    touch "$root/dev/$d"; mount --bind "/dev/$d" "$root/dev/$d"
  done
  mkdir -p "$root/dev/pts" "$root/dev/shm"
  mount -t devpts -o newinstance,ptmxmode=0666,mode=620 devpts "$root/dev/pts"
  ln -s pts/ptmx "$root/dev/ptmx"
  mount -t tmpfs -o mode=1777,nosuid,nodev tmpfs "$root/dev/shm"
  ln -s /proc/self/fd "$root/dev/fd"
  ln -s /proc/self/fd/0 "$root/dev/stdin"; ln -s /proc/self/fd/1 "$root/dev/stdout"
  ln -s /proc/self/fd/2 "$root/dev/stderr"
  mount -t tmpfs -o mode=1777,nosuid,nodev tmpfs "$root/tmp"
  chmod 1777 "$root/var/tmp"
  log "mounted /proc, /sys (ro), a private /dev (+ devpts, /dev/shm tmpfs), /tmp tmpfs"
  if [[ $cache != none ]]; then
    # Downloads only. apt's .deb files are linked in (not bind-mounted: apt locks its
    # archive folder, and several fresh roots may run at once) and new ones linked back out
    # after the run; pip's HTTP cache (http/ for pip < 23.3, as in Debian 12's venvs,
    # http-v2/ after) is bind-mounted, pip writes it atomically. Not pip's wheels/ (wheels
    # built here could hide a missing compiler), no venv, no installed package.
    mkdir -p "$cache/apt" "$root/var/cache/apt/archives/partial"
    find "$cache/apt" -maxdepth 1 -name '*.deb' -exec cp -l -t "$root/var/cache/apt/archives/" {} + 2>/dev/null ||
      find "$cache/apt" -maxdepth 1 -name '*.deb' -exec cp -t "$root/var/cache/apt/archives/" {} +
    for d in http http-v2; do
      mkdir -p "$cache/pip-$d" "$root/root/.cache/pip/$d"
      mount --bind "$cache/pip-$d" "$root/root/.cache/pip/$d"
    done
    # The wheelhouse: the files pip downloads for pinned venvs (scripts/step.sh's pip_pins, told
    # by PGLOSS_WHEELHOUSE below), as the index serves them — bpy alone is ~400 MB.
    mkdir -p "$cache/wheelhouse" "$root/var/cache/pgloss-wheelhouse"
    mount --bind "$cache/wheelhouse" "$root/var/cache/pgloss-wheelhouse"
    log "download caches from $cache: apt $(find "$cache/apt" -maxdepth 1 -name '*.deb' | wc -l) .deb files" \
      "($(du -sh "$cache/apt" | cut -f1)), pip $(du -shc "$cache/pip-http" "$cache/pip-http-v2" | tail -1 | cut -f1)," \
      "wheelhouse $(find "$cache/wheelhouse" -maxdepth 1 -type f ! -name .lock | wc -l) files ($(du -sh "$cache/wheelhouse" | cut -f1))"
  fi
  # dpkg without fsync (a throwaway root): faster installs, the same packages.
  echo force-unsafe-io >"$root/etc/dpkg/dpkg.cfg.d/99pgloss-unsafe-io"
  # apt keeps what it downloads, so that the cache fills (a fresh root has no docker-clean).
  echo 'Binary::apt-get::APT::Keep-Downloaded-Packages "true";' >"$root/etc/apt/apt.conf.d/99pgloss-keep-debs"

  env_args=(PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin HOME=/root
            LANG=C.UTF-8 USER=root LOGNAME=root SHELL=/bin/bash)
  [[ $cache != none ]] && env_args+=(PGLOSS_WHEELHOUSE=/var/cache/pgloss-wheelhouse)
  while (($#)) && [[ $1 =~ ^[A-Za-z_][A-Za-z0-9_]*= ]]; do env_args+=("$1"); shift; done
  stage "run"
  log "command: $*"
  log "environment: ${env_args[*]} (nothing else)"
  set +e
  chroot "$root" /usr/bin/env -i "${env_args[@]}" /bin/bash -c 'cd /root/pgloss && exec "$@"' bash "$@"
  rc=$?
  set -e
  stage ""
  if [[ $cache != none ]]; then  # new downloads back to the cache (same file name, same file)
    find "$root/var/cache/apt/archives" -maxdepth 1 -name '*.deb' -links 1 \
      -exec cp -n -l -t "$cache/apt/" {} + 2>/dev/null ||
      find "$root/var/cache/apt/archives" -maxdepth 1 -name '*.deb' -exec cp -n -t "$cache/apt/" {} +
  fi
  log "command exit status $rc; stage times: ${stage_times[*]}"
  exit "$rc"
fi

# ---------------------------------------------------------------------------------------
# Outside: check, make the root, enter the namespaces, clean up.
(($#)) || { sed -n '4,/^set -euo/{/^#/s/^# \{0,1\}//p}' "$0"; exit 2; }
[[ $(id -u) -eq 0 ]] || die "needs root (mmdebstrap's root mode, chroot, mounts)"
for tool in mmdebstrap git unshare chroot; do
  command -v "$tool" >/dev/null || die "$tool not found (bash scripts/bootstrap.sh apt mmdebstrap git)"
done

repo=$(cd "$(dirname "$0")/.." && pwd)
commit=$(git -C "$repo" rev-parse HEAD)
dirty=$(git -C "$repo" status --porcelain --untracked-files=no | wc -l)
if ((dirty)); then
  log "NOTE: $dirty uncommitted change(s) in $repo are NOT included; the root gets commit ${commit:0:12}"
fi
cache=${PGLOSS_FRESH_CACHE:-/var/cache/pgloss-fresh}
[[ $cache == none ]] || mkdir -p "$cache"

base=${TMPDIR:-/var/tmp}
# Roots left by a run killed with SIGKILL (no trap runs then): remove those whose runner is gone.
for old in "$base"/pgloss-fresh.*; do
  [[ -f $old.pid ]] || continue
  kill -0 "$(cat "$old.pid")" 2>/dev/null && continue
  log "removing a stale root $old"
  rm -rf --one-file-system "$old" "$old.pid"
done
root=$(mktemp -d "$base/pgloss-fresh.XXXXXX")
echo $$ >"$root.pid"
chmod 755 "$root"
cleanup() {
  local rc=$?
  trap - EXIT INT TERM HUP
  # unshare --fork ignores SIGTERM; SIGKILL it, and --kill-child takes everything inside.
  if [[ -n ${child:-} ]]; then kill -KILL "$child" 2>/dev/null; wait "$child" 2>/dev/null; fi
  if [[ ${PGLOSS_FRESH_KEEP:-0} == 1 ]]; then
    log "kept the root $root (PGLOSS_FRESH_KEEP=1; remove it with rm -rf --one-file-system)"
  else
    # The mounts were made in the namespace, which is gone: this is a plain directory tree.
    # --one-file-system guards the host's files even if something were still mounted.
    rm -rf --one-file-system "$root"
    log "removed the root $root"
  fi
  rm -f "$root.pid"
  exit "$rc"
}
trap cleanup EXIT
trap 'log "interrupted"; exit 130' INT
trap 'log "terminated"; exit 143' TERM HUP

log "fresh Debian 12 root $root for: $*"
t0=$SECONDS
# New mount namespace (private propagation: no mount reaches the host) and PID namespace:
# when this script dies, even by SIGKILL, unshare gets SIGKILL (setpriv --pdeathsig), its
# child, PID 1 inside, gets SIGKILL (--kill-child), and with it everything inside; the mounts
# go with the namespace. A root left by a SIGKILL is removed by the next run (above).
setpriv --pdeathsig KILL unshare --mount --propagation private --pid --fork --kill-child -- \
  "$BASH" "$repo/scripts/fresh-debian.sh" --inside "$root" "$repo" "$commit" "$cache" "$@" &
child=$!
set +e
wait "$child"
rc=$?
set -e
child=
log "total $((SECONDS - t0)) s, exit status $rc: $( ((rc == 0)) && echo PASSED || echo FAILED) — $*"
exit "$rc"
