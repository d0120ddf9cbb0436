#!/usr/bin/env bash
# Install the Debian packages mechverify's tests and reports use, when missing.
#   calculix-ccx     independent FEA solver for the cross-check tests and the benchmark
#   chromium         headless browser: the HTML report is rendered and screenshotted in the tests
#   poppler-utils    pdftotext / pdftoppm: the PDF report's text and pages are checked
#   libpango*        WeasyPrint (PDF reports) needs Pango
#   libglu1-mesa ... shared libraries the gmsh wheel links against
#   fonts-noto-core, fonts-noto-cjk  fallback fonts: non-Latin names and notes (CJK, Greek, ...) in PDF reports
#   fonts-noto-color-emoji  emoji in names and notes (found by fontconfig's fallback, never named in the CSS)
#   libsuitesparse-dev, libopenblas0-pthread  CHOLMOD for scikit-sparse (mechverify[direct]) and a BLAS that
#                    makes its supernodal factorisation fast (the reference BLAS is ~3x slower)
set -euo pipefail
need=()
# Read the font and library lists once: `ldconfig -p | grep -q` under pipefail fails when grep exits at the first
# match and ldconfig then dies of SIGPIPE, which made every run reinstall packages that were there.
fonts=$(fc-list 2>/dev/null || true)
libs=$(ldconfig -p 2>/dev/null || true)
has_font() { grep -qi "$1" <<<"$fonts"; }
has_lib() { grep -q "$1" <<<"$libs"; }
command -v ccx >/dev/null 2>&1 || need+=(calculix-ccx)
command -v chromium >/dev/null 2>&1 || need+=(chromium)
command -v pdftoppm >/dev/null 2>&1 || need+=(poppler-utils)
has_font "Noto Sans CJK" || need+=(fonts-noto-cjk)
has_font "NotoSans-Regular" || need+=(fonts-noto-core)
has_font "Noto Color Emoji" || need+=(fonts-noto-color-emoji)
[ -e /usr/include/suitesparse/cholmod.h ] || need+=(libsuitesparse-dev)
has_lib "libopenblas.so.0" || need+=(libopenblas0-pthread)
for lib in libpango-1.0.so.0:libpango-1.0-0 libpangoft2-1.0.so.0:libpangoft2-1.0-0 libGLU.so.1:libglu1-mesa \
           libXcursor.so.1:libxcursor1 libXinerama.so.1:libxinerama1 libXft.so.2:libxft2; do
  has_lib "${lib%%:*}" || need+=("${lib##*:}")
done
[ ${#need[@]} -eq 0 ] && exit 0
cmd="apt-get update && apt-get install -y --no-install-recommends ${need[*]}"
if [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null 2>&1; then
  echo "Installing system packages: ${need[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq && apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
else
  echo "mechverify needs these system packages: ${need[*]}" >&2
  echo "Run:  sudo sh -c '$cmd'" >&2
  exit 1
fi
