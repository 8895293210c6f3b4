#!/usr/bin/env bash
# `candela info --json` against closed forms, through the public command on
# files written here: a cosine (pi I0), a cone (2 pi I0 (1 - cos tau)) in
# EULUMDAT, the same cosine as type B and type A, and beam / field angles
# in each plane (cos gamma in one plane, cos^2 gamma in the other).
set -u
: "${CANDELA:?}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; fail=1; fi; }
# the JSON on one line, then one number by its path (key, or object.key)
json() { "$CANDELA" info --json "$1" | tr -d '\n\t '; }
num() {
  case $2 in
    *.*) sed -n "s/.*\"${2%%.*}\":{[^}]*\"${2#*.}\":\([-0-9.eE+]*\).*/\1/p" <<<"$1" ;;
    *) sed -n "s/.*\"$2\":\([-0-9.eE+]*\).*/\1/p" <<<"$1" ;;
  esac
}
# |a - b| <= t (absolute)
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a != "" && d <= t) }'; }

# An IES type T file: horizontal angles H (awk list), vertical V, value f(h, v) in awk.
ies() { # file type "h0 h1 ..." "v0 v1 ..." awk-expression-of-h-and-v
  awk -v type="$2" -v hs="$3" -v vs="$4" "
    function d2r(x) { return x * 3.14159265358979323846 / 180 }
    function f(h, v) { return $5 }
    BEGIN {
      nh = split(hs, H, \" \"); nv = split(vs, V, \" \")
      printf \"IESNA:LM-63-2002\n[TEST] closed form\nTILT=NONE\n1 -1 1 %d %d %d 2 0 0 0\n1 1 0\n\", nv, nh, type
      for (j = 1; j <= nv; ++j) printf \"%.17g\n\", V[j]
      for (i = 1; i <= nh; ++i) printf \"%.17g\n\", H[i]
      for (i = 1; i <= nh; ++i) for (j = 1; j <= nv; ++j) printf \"%.17g\n\", f(H[i], V[j])
    }" >"$1"
}
seq_list() { awk -v a="$1" -v b="$2" -v s="$3" 'BEGIN { for (x = a; x <= b + 1e-9; x += s) printf "%s%.10g", (x > a ? " " : ""), x }'; }

pi=3.14159265358979323846
i0=1500

# I0 cos(gamma), 0.5 degree steps, one plane: pi I0. The linear interpolant of
# cos lies within h^2/8 = 9.5e-6 of it (h in radians): tolerance 2e-5 relative.
ies "$tmp/cos.ies" 1 "0" "$(seq_list 0 90 0.5)" "$i0 * cos(d2r(v))"
j=$(json "$tmp/cos.ies")
want=$(awk -v p=$pi -v i=$i0 'BEGIN { printf "%.17g", p * i }')
check "cosine: flux pi I0 = $want lm (got $(num "$j" flux_lm))" 'near "$(num "$j" flux_lm)" "$want" "$(awk -v w="$want" "BEGIN{print 2e-5 * w}")"'
check "cosine: all of it downward" 'near "$(num "$j" downward_fraction)" 1 1e-12'
check "cosine: beam angle 120 deg in both planes" 'near "$(num "$j" beam_angle_deg.c0_c180)" 120 0.005 && near "$(num "$j" beam_angle_deg.c90_c270)" 120 0.005'
field=$(awk 'BEGIN { x = 0.1; printf "%.12g", 2 * atan2(sqrt(1 - x * x), x) * 180 / 3.14159265358979323846 }')
check "cosine: field angle 2 acos(0.1) = $field deg" 'near "$(num "$j" field_angle_deg.c0_c180)" "$field" 0.005'

# The same cosine as type B and type A (H, V in -90..90, 1 degree steps):
# I0 cos H cos V. Each integrates to pi I0 within its interpolation error
# (h^2/8 = 3.8e-5 for each factor: tolerance 1e-4), like the type C table.
for type in 2 3; do
  ies "$tmp/type$type.ies" $type "$(seq_list -90 90 1)" "$(seq_list -90 90 1)" "$i0 * cos(d2r(h)) * cos(d2r(v))"
  j=$(json "$tmp/type$type.ies")
  check "type $type cosine: flux pi I0 (got $(num "$j" flux_lm))" 'near "$(num "$j" flux_lm)" "$want" "$(awk -v w="$want" "BEGIN{print 1e-4 * w}")"'
  check "type $type cosine: photometric type named" '[[ "$j" == *"\"photometric_type\":\"$( [ $type = 2 ] && echo B || echo A)\""* ]]'
done

# Quadrant table: cos gamma in the H0 plane, cos^2 gamma in the H90 plane.
# Beam and field angles are per plane: 120 and 2 acos 0.1; 90 and 2 acos sqrt 0.1.
ies "$tmp/quad.ies" 1 "$(seq_list 0 90 15)" "$(seq_list 0 90 0.5)" \
    "$i0 * ((1 - sin(d2r(h))^2) * cos(d2r(v)) + sin(d2r(h))^2 * cos(d2r(v))^2)"
j=$(json "$tmp/quad.ies")
field90=$(awk 'BEGIN { x = sqrt(0.1); printf "%.12g", 2 * atan2(sqrt(1 - x * x), x) * 180 / 3.14159265358979323846 }')
check "quadrant: beam 120 deg in C0-C180 (got $(num "$j" beam_angle_deg.c0_c180))" 'near "$(num "$j" beam_angle_deg.c0_c180)" 120 0.005'
check "quadrant: beam 90 deg in C90-C270 (got $(num "$j" beam_angle_deg.c90_c270))" 'near "$(num "$j" beam_angle_deg.c90_c270)" 90 0.005'
check "quadrant: field $field90 deg in C90-C270" 'near "$(num "$j" field_angle_deg.c90_c270)" "$field90" 0.005'
check "quadrant: symmetry named" '[[ "$j" == *"\"symmetry\":\"quadrant\""* ]]'

# A cone of 1500 cd to tau = 30 degrees, nothing beyond, in EULUMDAT (Isym 1,
# gamma 0..30; 1500 cd/klm of a 1000 lm lamp): 2 pi I0 (1 - cos tau) exactly,
# LOR = that / 1000 lm.
{
  printf 'cone\r\n1\r\n1\r\n1\r\n0\r\n7\r\n5\r\nr\r\nn\r\nn\r\nf\r\nd\r\n'
  printf '0\r\n0\r\n0\r\n0\r\n0\r\n0\r\n0\r\n0\r\n0\r\n100\r\n100\r\n1\r\n0\r\n1\r\n'
  printf '1\r\nL\r\n1000\r\nc\r\nr\r\n1\r\n'
  for k in 1 2 3 4 5 6 7 8 9 10; do printf '0\r\n'; done
  printf '0\r\n'
  for g in 0 5 10 15 20 25 30; do printf '%s\r\n' "$g"; done
  for g in 0 5 10 15 20 25 30; do printf '1500\r\n'; done
} >"$tmp/cone.ldt"
j=$("$CANDELA" info --json "$tmp/cone.ldt" 2>/dev/null | tr -d '\n\t ')
want=$(awk -v p=$pi -v i=$i0 'BEGIN { printf "%.17g", 2 * p * i * (1 - cos(p / 6)) }')
check "cone: flux 2 pi I0 (1 - cos 30) = $want lm (got $(num "$j" flux_lm))" 'near "$(num "$j" flux_lm)" "$want" "$(awk -v w="$want" "BEGIN{print 1e-12 * w}")"'
check "cone: lamp flux 1000 lm, LOR flux/1000" 'near "$(num "$j" lamp_flux_lm)" 1000 0 && near "$(num "$j" lor)" "$(awk -v w="$want" "BEGIN{printf \"%.17g\", w / 1000}")" 1e-12'
check "cone: beam and field angles 60 deg (a hard edge at 30)" 'near "$(num "$j" beam_angle_deg.c0_c180)" 60 1e-6 && near "$(num "$j" field_angle_deg.c90_c270)" 60 1e-6'
exit $fail
