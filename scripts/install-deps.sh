#!/usr/bin/env bash
# Installs the Debian 12 packages the project builds and tests with, skipping what is present.
# Run as root. Every dependency of the project is listed here and nowhere else.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config clang-format
  clang lld libclang-rt-14-dev  # the sanitizer and fuzz builds (lld: their linker)
  libosmesa6-dev libopenimageio-dev openimageio-tools libpng-dev libglfw3-dev libglm-dev libassimp-dev
  libjpeg-dev  # shared screens' JPEG frames (image/jpeg_frame.hpp), decoded with libjpeg itself
  libegl-dev libegl-mesa0  # --renderer egl: glvnd's libEGL and Mesa's EGL driver (llvmpipe without a GPU)
  fonts-dejavu-core
  libavformat-dev libavcodec-dev libswscale-dev libavutil-dev ffmpeg
  libcli11-dev libtomlplusplus-dev libfmt-dev nlohmann-json3-dev libzstd-dev liblz4-dev
  libtinyxml2-dev libzip-dev  # tilelayout import of MPCDI calibrations: mpcdi.xml, the zip archive
  libcpp-httplib-dev  # the control page's HTTP server (control_page/)
  liblo-dev  # OSC decoding of TUIO touch input (touch/)
  libgtest-dev libgmock-dev libbenchmark-dev
  assimp-testmodels  # real-world models (the Khronos glTF samples) a model test loads
  libopenmpi-dev openmpi-bin
  socat iproute2 nftables curl jq xvfb xauth libx11-dev libxrandr-dev libxtst-dev
  gnuplot-nox
  libvncserver-dev  # --scene vnc: the coordinator's RFB client (libvncclient)
  tigervnc-standalone-server tigervnc-tools x11-xserver-utils  # its test: Xvnc, vncpasswd, xsetroot
  chromium  # the control page's browser test (tests/browser/)
)
# Node.js and npm drive that browser (playwright-core, which downloads no browser): Debian's,
# unless the machine already has a Node.js of its own with npm.
command -v npm >/dev/null 2>&1 || PACKAGES+=(nodejs npm)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]})); then
  echo "install-deps: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
  echo "install-deps: all ${#PACKAGES[@]} packages present"
fi

# playwright-core for the browser test, at the version package-lock.json pins, from npm.
browser_tests="$(dirname "$0")/../tests/browser"
if [[ ! -d $browser_tests/node_modules/playwright-core ]]; then
  echo "install-deps: npm ci in tests/browser (playwright-core)"
  (cd "$browser_tests" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
fi
