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
