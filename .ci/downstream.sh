#!/usr/bin/env bash
# Builds .ci/downstream from the packaged crates alone, as crates.io would
# serve them: the `.crate` files in target/package unpacked into a local
# (directory) registry beside their crates.io dependencies, vendored, and
# crates.io replaced by it; no path dependency, offline. Run after
# `cargo package` of every published crate.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
registry=$root/target/packaged-registry
work=$root/target/downstream
rm -rf "$registry" "$work"
mkdir -p "$registry"
cp -r .ci/downstream "$work"

# The packaged crates, each with the checksum of its .crate file.
patches=""
for crate in target/package/speclab*-0.1.0.crate; do
    name=$(basename "$crate" .crate)
    tar -xzf "$crate" -C "$registry"
    sum=$(sha256sum "$crate" | cut -d' ' -f1)
    printf '{"files":{},"package":"%s"}' "$sum" > "$registry/$name/.cargo-checksum.json"
    package=${name%-0.1.0}
    patches="$patches$package = { path = \"$registry/$name\" }"$'\n'
done

# Their crates.io dependencies, vendored beside them (resolved once with the
# packaged crates patched in, then the patch removed).
cp "$work/Cargo.toml" "$work/Cargo.toml.plain"
printf '\n[patch.crates-io]\n%s' "$patches" >> "$work/Cargo.toml"
cargo vendor --quiet --manifest-path "$work/Cargo.toml" --versioned-dirs "$work/vendor" > /dev/null
mv "$work/vendor"/* "$registry"/
mv "$work/Cargo.toml.plain" "$work/Cargo.toml"
rm -f "$work/Cargo.lock"

mkdir -p "$work/.cargo"
cat > "$work/.cargo/config.toml" <<CONFIG
[source.crates-io]
replace-with = "packaged"
[source.packaged]
directory = "$registry"
CONFIG
# Cargo reads the replacement from the directory it runs in.
(cd "$work" && cargo run --quiet --offline --release)
if grep -q 'path+' "$work/Cargo.lock"; then
    echo "error: the downstream crate resolved a path dependency" >&2
    exit 1
fi
