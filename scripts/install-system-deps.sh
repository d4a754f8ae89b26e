#!/usr/bin/env bash
# System packages the test suite and the workbench need beyond PyPI (Debian/Ubuntu):
#   chromium           renders the workbench's HTML report in a headless browser test
#   fonts-dejavu-core  the fonts of the glyph-outline corpus (build123d Text)
# Installs only what is missing; uses sudo when not root.
set -euo pipefail
need=()
command -v chromium >/dev/null 2>&1 || need+=(chromium)
if ! ls /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf >/dev/null 2>&1; then need+=(fonts-dejavu-core); fi
if [ ${#need[@]} -eq 0 ]; then exit 0; fi
SUDO=""
if [ "$(id -u)" != "0" ]; then SUDO="sudo"; fi
echo "installing system packages: ${need[*]}" >&2
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${need[@]}" >/dev/null
