#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the Debian packages the package, its tool and its tests need.
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends \
  build-essential cmake \
  libcgal-dev libeigen3-dev libboost-dev libboost-program-options-dev \
  libgmp-dev libmpfr-dev libgtest-dev nlohmann-json3-dev libtbb-dev >/dev/null
echo "install-deps: dependencies installed"
