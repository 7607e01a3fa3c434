#!/usr/bin/env bash
# Makes a DDS Security keystore for the scanfilter pipeline with openssl only,
# in the layout ROS 2's sros2 uses, so a ROS 2 node can join with its own
# enclave (made here with --add-enclave, or by `ros2 security create_enclave`):
#
#   KEYSTORE/public/{identity_ca,permissions_ca}.cert.pem   the two CAs
#   KEYSTORE/private/{identity_ca,permissions_ca}.key.pem   their keys (keep off the robot)
#   KEYSTORE/enclaves/governance.{xml,p7s}                  domain rules, signed by the permissions CA
#   KEYSTORE/enclaves/<root>/<name>/                        one per participant: cert.pem, key.pem,
#       identity_ca.cert.pem, permissions_ca.cert.pem, governance.p7s, permissions.{xml,p7s}
#
# Keys are ECDSA P-256 (as sros2's); the governance and permissions are S/MIME
# signed (clear text, detached signature) as sros2 signs them. An enclave
# holds copies, not links, so that it can be copied to a robot on its own.
#
#   make-keystore.sh [--domain ID] [--namespace NS] [--root PATH] [--days N] KEYSTORE
#       the CAs and governance (unless already there) and the enclaves
#       <root>/{scan_ingest,jump_filter,penetration_filter,map_publisher,recorder,driver}
#   make-keystore.sh [--domain ID] [--namespace NS] [--days N] --add-enclave PATH
#                    [--publish "TOPIC..."] [--subscribe "TOPIC..."] KEYSTORE
#       one more enclave (e.g. a ROS 2 node's) with exactly these topics
#
# Topics are ROS names: "scan" is rt/<NS>/scan, "/scan" is rt/scan; a name
# given as dds:NAME is the DDS topic NAME as is (ROS 2's own, e.g.
# dds:ros_discovery_info, dds:rq/my_node/*, dds:rr/my_node/*); DDS
# wildcards (* ?) are allowed. Each service may publish only its outputs and
# subscribe only to its inputs (docs/operations.md, DDS Security).
set -euo pipefail
set -o noglob  # topic lists hold DDS wildcards (* ?): never expand them against files

DOMAIN=0
NAMESPACE=""
ROOT=/scanfilter
DAYS=3650
ADD_ENCLAVE=""
PUBLISH=""
SUBSCRIBE=""
# Permissions start to be valid a day early, so that a robot whose clock lags
# the machine that made the keystore by less than that accepts them.
# (Certificates start when made: openssl 3.0's x509 cannot backdate them, so
# make the keystore on a machine whose clock is not ahead of the robots'.)
CLOCK_SKEW_DAYS=1

usage() { sed -n '2,28s/^# \{0,1\}//p' "$0"; }
PROGRAM=$(basename "$0")  # scanfilter-make-keystore where installed
die() { echo "$PROGRAM: $*" >&2; exit 2; }

while [ $# -gt 0 ]; do
  case "$1" in
    --domain) DOMAIN="${2:?--domain needs an id}"; shift 2 ;;
    --namespace) NAMESPACE="${2?--namespace needs a value}"; shift 2 ;;
    --root) ROOT="${2:?--root needs a path}"; shift 2 ;;
    --days) DAYS="${2:?--days needs a number}"; shift 2 ;;
    --add-enclave) ADD_ENCLAVE="${2:?--add-enclave needs a path}"; shift 2 ;;
    --publish) PUBLISH="${2?}"; shift 2 ;;
    --subscribe) SUBSCRIBE="${2?}"; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    -*) die "unknown option $1 (--help lists them)" ;;
    *) break ;;
  esac
done
[ $# = 1 ] || { usage >&2; exit 2; }
KS="$1"
[[ "$DOMAIN" =~ ^[0-9]+$ ]] && [ "$DOMAIN" -le 232 ] || die "--domain: expected a DDS domain id 0-232, got \"$DOMAIN\""
[[ "$DAYS" =~ ^[1-9][0-9]*$ ]] || die "--days: expected a positive number of days, got \"$DAYS\""
[[ "$ROOT" == /* ]] || die "--root: expected an absolute enclave path like /scanfilter, got \"$ROOT\""
# The services' own rule (topicNamespaceProblem): a ROS name without spaces, '#' or a leading or trailing '/'.
[[ "$NAMESPACE" != /* && "$NAMESPACE" != */ && "$NAMESPACE" != *[[:space:]#]* ]] ||
  die "--namespace: expected a ROS name without spaces or leading/trailing '/', got \"$NAMESPACE\""
command -v openssl > /dev/null || die "openssl is not installed"

PUB="$KS/public" PRIV="$KS/private" ENC="$KS/enclaves"

# openssl's -subj splits at '/': escape those of the enclave path.
subject_arg() { echo "/CN=${1//\//\\/}"; }

new_key() { openssl genpkey -algorithm EC -pkeyopt ec_paramgen_curve:P-256 -out "$1" 2> /dev/null; chmod 600 "$1"; }

make_ca() {  # name common-name
  [ -f "$PUB/$1.cert.pem" ] && [ -f "$PRIV/$1.key.pem" ] && return 0
  new_key "$PRIV/$1.key.pem"
  openssl req -new -x509 -sha256 -key "$PRIV/$1.key.pem" -out "$PUB/$1.cert.pem" -days "$DAYS" \
    -subj "/CN=$2" -addext "basicConstraints=critical,CA:TRUE"
}

sign() {  # in out: S/MIME, clear text with a detached signature, by the permissions CA
  openssl smime -sign -text -in "$1" -out "$2" -signer "$PUB/permissions_ca.cert.pem" \
    -inkey "$PRIV/permissions_ca.key.pem"
}

iso_date() { date -u -d "$1" +%Y-%m-%dT%H:%M:%S; }

make_governance() {
  if [ -f "$ENC/governance.p7s" ]; then
    local rules
    rules=$(cat "$ENC/governance.xml")
    grep -q "<id>$DOMAIN</id>" <<<"$rules" ||
      die "$ENC/governance.xml covers another domain than --domain $DOMAIN: use a new keystore per domain"
    return 0
  fi
  cat > "$ENC/governance.xml" <<XML
<?xml version="1.0" encoding="UTF-8"?>
<!-- scanfilter's domain rules (deploy/security/make-keystore.sh): only
     authenticated participants join; discovery, liveliness, every RTPS
     message and every topic's data are encrypted; reading and writing any
     topic needs a grant in the participant's signed permissions. -->
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
    xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_governance.xsd">
  <domain_access_rules>
    <domain_rule>
      <domains><id>$DOMAIN</id></domains>
      <allow_unauthenticated_participants>false</allow_unauthenticated_participants>
      <enable_join_access_control>true</enable_join_access_control>
      <discovery_protection_kind>ENCRYPT</discovery_protection_kind>
      <liveliness_protection_kind>ENCRYPT</liveliness_protection_kind>
      <rtps_protection_kind>ENCRYPT</rtps_protection_kind>
      <topic_access_rules>
        <topic_rule>
          <topic_expression>*</topic_expression>
          <enable_discovery_protection>true</enable_discovery_protection>
          <enable_liveliness_protection>true</enable_liveliness_protection>
          <enable_read_access_control>true</enable_read_access_control>
          <enable_write_access_control>true</enable_write_access_control>
          <metadata_protection_kind>ENCRYPT</metadata_protection_kind>
          <data_protection_kind>ENCRYPT</data_protection_kind>
        </topic_rule>
      </topic_access_rules>
    </domain_rule>
  </domain_access_rules>
</dds>
XML
  sign "$ENC/governance.xml" "$ENC/governance.p7s"
}

dds_topic() {  # ROS name -> DDS topic name
  case "$1" in
    dds:*) echo "${1#dds:}" ;;
    /*) echo "rt$1" ;;
    *) if [ -n "$NAMESPACE" ]; then echo "rt/$NAMESPACE/$1"; else echo "rt/$1"; fi ;;
  esac
}

topics_xml() {  # element "topic..."
  local t
  [ -n "$2" ] || return 0
  echo "          <$1><topics>"
  for t in $2; do echo "            <topic>$(dds_topic "$t")</topic>"; done
  echo "          </topics></$1>"
}

make_enclave() {  # path "published topics" "subscribed topics"
  local dir="$ENC$1"
  mkdir -p "$dir"
  cp "$PUB/identity_ca.cert.pem" "$PUB/permissions_ca.cert.pem" "$ENC/governance.p7s" "$dir/"
  new_key "$dir/key.pem"
  openssl req -new -sha256 -key "$dir/key.pem" -subj "$(subject_arg "$1")" -out "$dir/cert.csr"
  openssl x509 -req -sha256 -in "$dir/cert.csr" -CA "$PUB/identity_ca.cert.pem" -CAkey "$PRIV/identity_ca.key.pem" \
    -CAserial "$PRIV/identity_ca.srl" -CAcreateserial -days "$DAYS" -out "$dir/cert.pem" 2> /dev/null
  rm "$dir/cert.csr"
  cat > "$dir/permissions.xml" <<XML
<?xml version="1.0" encoding="UTF-8"?>
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
    xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_permissions.xsd">
  <permissions>
    <grant name="$1">
      <subject_name>CN=$1</subject_name>
      <validity>
        <not_before>$(iso_date "-$CLOCK_SKEW_DAYS days")</not_before>
        <not_after>$(iso_date "+$DAYS days")</not_after>
      </validity>
      <allow_rule>
        <domains><id>$DOMAIN</id></domains>
$(topics_xml publish "$2")
$(topics_xml subscribe "$3")
      </allow_rule>
      <default>DENY</default>
    </grant>
  </permissions>
</dds>
XML
  sign "$dir/permissions.xml" "$dir/permissions.p7s"
  echo "enclave $1: publish [$(for t in $2; do printf ' %s' "$(dds_topic "$t")"; done) ]" \
       "subscribe [$(for t in $3; do printf ' %s' "$(dds_topic "$t")"; done) ]"
}

mkdir -p "$PUB" "$PRIV" "$ENC"
chmod 700 "$PRIV"
if [ -n "$ADD_ENCLAVE" ]; then
  [[ "$ADD_ENCLAVE" == /* ]] || die "--add-enclave: expected an absolute enclave path like /robot/driver, got \"$ADD_ENCLAVE\""
  [ -f "$ENC/governance.p7s" ] || die "$KS is not a keystore yet: run $PROGRAM $KS first"
  make_governance  # only checks that it covers --domain
  make_enclave "$ADD_ENCLAVE" "$PUBLISH" "$SUBSCRIBE"
  exit 0
fi
[ -z "$PUBLISH$SUBSCRIBE" ] || die "--publish and --subscribe go with --add-enclave"
make_ca identity_ca "scanfilter Identity CA"
make_ca permissions_ca "scanfilter Permissions CA"
make_governance
# Each service: publish its outputs, subscribe to its inputs, nothing else.
make_enclave "$ROOT/scan_ingest" "posed_scan" "scan odom"
make_enclave "$ROOT/jump_filter" "jump_filtered_scan" "posed_scan"
make_enclave "$ROOT/penetration_filter" "labeled_scan scan_filtered" "jump_filtered_scan"
make_enclave "$ROOT/map_publisher" "map map_updates" "labeled_scan"
# Operators' and tests' monitor (dds_tools/scan_recorder): reads every stage's output, publishes nothing.
make_enclave "$ROOT/recorder" "" "posed_scan jump_filtered_scan labeled_scan scan_filtered map map_updates"
# A robot driver feeding the live ingest: LaserScan and Odometry only.
make_enclave "$ROOT/driver" "scan odom" ""
echo "keystore: $KS (domain $DOMAIN, topics under $(dds_topic x | sed 's#/x$##'), valid $DAYS days)"
