#!/usr/bin/env bash
# Installs the pinned system tools of scripts/tools.lock (Debian bookworm).
# Called by ./run when a tool is missing; safe to run by hand.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
lock="$here/tools.lock"

pkgs=()
while read -r pkg ver _cmd; do
  [[ -z "${pkg:-}" || "$pkg" == \#* ]] && continue
  pkgs+=("$pkg=$ver")
done <"$lock"

if [[ $(id -u) -eq 0 ]]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1; then
  sudo=(sudo)
else
  echo "error: installing ${pkgs[*]} needs root; run scripts/install-tools.sh as root" >&2
  exit 1
fi
if ! command -v apt-get >/dev/null 2>&1; then
  echo "error: no apt-get here; install these by hand: ${pkgs[*]} (see scripts/tools.lock)" >&2
  exit 1
fi
echo "installing pinned tools: ${pkgs[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${pkgs[@]}" >/dev/null
echo "tools installed" >&2
