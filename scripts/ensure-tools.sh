#!/usr/bin/env bash
# Installs the pinned tools (scripts/install-tools.sh) if any is missing.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
missing=()
while read -r pkg _ver cmd; do
  [[ -z "${pkg:-}" || "$pkg" == \#* ]] && continue
  command -v "$cmd" >/dev/null 2>&1 || missing+=("$cmd")
done <"$here/tools.lock"
if ((${#missing[@]})); then
  echo "missing tools: ${missing[*]}" >&2
  "$here/install-tools.sh"
fi

# The YoWASP synthesis tools (merkur synth): a venv made from the lock, remade
# when the lock or the venv's stack setting changes.
venv="$here/../.tools/venv"
want=$(cat "$here/requirements-synth.txt" "$here/yowasp_sitecustomize.py" | sha256sum | cut -d' ' -f1)
if [[ "$(cat "$venv/lock.sha256" 2>/dev/null)" != "$want" ]]; then
  "$here/install-tools.sh" --synth
fi
