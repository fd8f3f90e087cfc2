# Sourced by scripts/build_exodiff.sh and scripts/build_trilinos_openmp.sh: fetches and unpacks
# Debian's trilinos *source* package (13.2.0-4: 166 MB download, 828 MB unpacked).
# Callers define say() (progress to stderr) and set sudo_cmd ("" as root, "sudo" otherwise).

# Enables a deb-src stanza for Debian bookworm main when none is present, installs the listed
# Debian packages when missing (apt-get update first when either is needed).
efg_prepare_source_tools() {
  local need_update=0
  if ! grep -rqsE '^(deb-src[[:space:]].*bookworm[[:space:]].*main|Types:.*deb-src)' \
    /etc/apt/sources.list /etc/apt/sources.list.d/ >/dev/null 2>&1; then
    say "enabling a deb-src stanza for Debian bookworm main"
    $sudo_cmd tee /etc/apt/sources.list.d/efg-deb-src.sources >/dev/null <<'SOURCES'
# Added by efg scripts/lib/trilinos_source.sh: Debian's trilinos source package (SEACAS exodiff,
# the OpenMP Trilinos build).
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SOURCES
    need_update=1
  fi
  local missing=() p
  for p in "$@"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$p")
    fi
  done
  if [ $need_update -eq 1 ] || [ ${#missing[@]} -gt 0 ]; then
    $sudo_cmd apt-get update -qq
  fi
  if [ ${#missing[@]} -gt 0 ]; then
    say "installing ${missing[*]}"
    DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends \
      "${missing[@]}" >/dev/null
  fi
}

# Downloads and unpacks the source package into "$1/trilinos" (the folder is created, and
# emptied first). The download folder is removed after unpacking.
efg_fetch_trilinos_source() {
  local work="$1"
  rm -rf "$work"
  mkdir -p "$work/download"
  say "downloading Debian's trilinos source package (166 MB) into $work"
  (cd "$work/download" && apt-get source --download-only -qq trilinos >/dev/null 2>&1) || {
    say "apt-get source trilinos failed; check the deb-src stanza and the network"; return 1; }
  local dsc
  dsc=$(ls "$work"/download/trilinos_*.dsc | head -1)
  say "unpacking $(basename "$dsc")"
  dpkg-source -x -q --no-check "$dsc" "$work/trilinos" >/dev/null 2>&1
  rm -rf "$work/download"
}
