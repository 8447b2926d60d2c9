#!/usr/bin/env bash
# Peers outside Rust: colour-science and numpy on the same spectra as
# `cargo bench --bench peers` (F11 × H4, and 36-sample reflectances).
# Not run by CI. Creates a virtual environment under target/peers-venv.
#
#     tools/python-peers/run.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
venv=target/peers-venv
if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv"
    "$venv/bin/pip" install --quiet numpy colour-science
fi
"$venv/bin/python" tools/python-peers/peers.py
