# Shared by the end-to-end scripts that use network namespaces (after lib.sh): root and iproute2
# or skip (77), namespaces this test creates and removes on exit, and the Cyclone configuration
# pinned to one interface of them.
[ "$(id -u)" -eq 0 ] || { echo "skip: network namespaces need root"; exit 77; }
command -v ip >/dev/null || { echo "skip: no ip (iproute2)"; exit 77; }

NAMESPACES=()
remove_namespaces() {
  # Deleting a namespace kills nothing by itself: stop what runs in it first (bounded).
  for ns in "${NAMESPACES[@]}"; do
    for _ in 1 2 3 4 5 6 7 8 9 10; do
      pids=$(ip netns pids "$ns" 2>/dev/null || true)
      [ -z "$pids" ] && break
      kill $pids 2>/dev/null || true
      sleep 0.2
    done
    ip netns pids "$ns" 2>/dev/null | xargs -r kill -9 2>/dev/null || true
    ip netns del "$ns" 2>/dev/null || true
  done
}
trap 'remove_namespaces; cleanup' EXIT

add_namespace() {  # add_namespace NAME: skips the test when namespaces cannot be made here
  ip netns add "$1" || { echo "skip: cannot create a network namespace"; exit 77; }
  NAMESPACES+=("$1")
  ip -n "$1" link set lo up
}

# Cyclone on one interface only (multicast stays on the test's private link), with peers.
dds_xml() {  # dds_xml INTERFACE PEER_ADDRESS...
  local interface=$1 peers=""
  shift
  for p in "$@"; do peers+="<Peer Address=\"$p\"/>"; done
  echo "<CycloneDDS><Domain Id=\"any\"><General><Interfaces><NetworkInterface name=\"$interface\" \
multicast=\"true\"/></Interfaces><AllowMulticast>true</AllowMulticast></General><Discovery>\
<Tag>$TAG</Tag><Peers>$peers</Peers><LeaseDuration>2s</LeaseDuration></Discovery></Domain>\
</CycloneDDS>"
}
