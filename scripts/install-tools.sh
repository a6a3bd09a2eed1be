#!/usr/bin/env bash
# Installs the pinned system tools of scripts/tools.lock (Debian bookworm)
# and, with `--synth`, the pinned PyPI synthesis tools of
# scripts/requirements-synth.txt into .tools/venv (no root needed for that
# part). Called by ./run when a tool is missing; safe to run by hand:
#   scripts/install-tools.sh          Debian packages (root or sudo)
#   scripts/install-tools.sh --synth  only the YoWASP venv
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
lock="$here/tools.lock"

if [[ "${1:-}" == "--synth" ]]; then
  venv="$here/../.tools/venv"
  req="$here/requirements-synth.txt"
  echo "installing pinned synthesis tools into .tools/venv (scripts/requirements-synth.txt)" >&2
  rm -rf "$venv"
  python3 -m venv "$venv"
  "$venv/bin/pip" install -q --disable-pip-version-check --require-hashes -r "$req"
  # A larger WebAssembly stack for the YoWASP tools (see the file).
  site=$("$venv/bin/python3" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
  cp "$here/yowasp_sitecustomize.py" "$site/sitecustomize.py"
  # The stamp says which lock and stack setting the venv was made from
  # (ensure-tools.sh).
  cat "$req" "$here/yowasp_sitecustomize.py" | sha256sum | cut -d' ' -f1 >"$venv/lock.sha256"
  echo "synthesis tools installed" >&2
  exit 0
fi

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
