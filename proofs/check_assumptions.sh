#!/bin/sh
# Fails unless
#  (1) no source file uses the vernacular that admits or postulates facts
#      (the keyword list KW below),
#  (2) every `Theorem` of the sources is checked in Assumptions.v, which is
#      exactly what gen_assumptions.sh writes from the sources, and
#  (3) `Print Assumptions` of every Theorem lists only the axioms of the
#      standard library's real numbers (whitelist below).
set -eu
cd "$(dirname "$0")"
COQC=${COQC:-coqc}
SOURCES=$(grep -v '^-' _CoqProject)

status=0

# (1) forbidden vernacular
# spelled in pieces so that this script itself does not contain the keywords
KW="Ad""mitted|ad""mit|Ax""iom|Ax""ioms|Para""meter|Para""meters|Hypo""thesis|Hypo""theses|Conj""ecture"
if grep -nwE "$KW" $SOURCES Assumptions.v; then
  echo "check-assumptions: forbidden keyword found (see above)" >&2
  status=1
fi

# (2) every Theorem is listed in Assumptions.v
theorems=$(grep -h '^Theorem ' $SOURCES | awk '{print $2}')
count=0
for t in $theorems; do
  count=$((count + 1))
  if ! grep -qx "Print Assumptions $t\." Assumptions.v; then
    echo "check-assumptions: Theorem $t is not printed in Assumptions.v" >&2
    status=1
  fi
done
generated=$(mktemp)
sh ./gen_assumptions.sh "$generated"
if ! cmp -s "$generated" Assumptions.v; then
  diff "$generated" Assumptions.v >&2 || true
  echo "check-assumptions: Assumptions.v is not gen_assumptions.sh's output (make -C proofs assumptions)" >&2
  status=1
fi
rm -f "$generated"
dups=$(echo "$theorems" | sort | uniq -d)
if [ -n "$dups" ]; then
  echo "check-assumptions: duplicate Theorem names: $dups" >&2
  status=1
fi

# (3) compile Assumptions.v and inspect its output
# Assumptions.v in two halves compiled at once (each `Print Assumptions` walks the
# whole proof term; one file took nearly 3 minutes): the Require lines, then the
# first or the second half of the Check/Print pairs, the outputs joined in order.
header=$(grep -n '^From PhongApprox Require' Assumptions.v | tail -1 | cut -d: -f1)
prints=$(grep -c '^Print Assumptions ' Assumptions.v)
for half in 1 2; do
  { head -n "$header" Assumptions.v
    tail -n +"$((header + 1))" Assumptions.v | awk -v half="$half" -v mid="$((prints / 2))" '
      { if ((seen < mid) == (half == 1)) print }
      /^Print Assumptions / { seen++ }'
  } > "Assumptions_half$half.v"
done
$COQC -Q . PhongApprox -w -ambiguous-paths Assumptions_half1.v > assumptions_half1.log &
pid=$!
half2=0
$COQC -Q . PhongApprox -w -ambiguous-paths Assumptions_half2.v > assumptions_half2.log || half2=$?
half1=0
wait "$pid" || half1=$?
cat assumptions_half1.log assumptions_half2.log > assumptions.log
rm -f Assumptions_half1.* Assumptions_half2.* .Assumptions_half1.aux .Assumptions_half2.aux assumptions_half1.log assumptions_half2.log
if [ "$half1" -ne 0 ] || [ "$half2" -ne 0 ]; then
  echo "check-assumptions: Assumptions.v does not compile" >&2
  exit 1
fi
names_file=$(mktemp)
echo "$theorems" > "$names_file"
if ! awk -v names="$names_file" '
  BEGIN {
    while ((getline l < names) > 0) thm[l] = 1
    # Postulates of the standard library real numbers (Coq >= 8.13) and the
    # classical / extensionality axioms that Reals and Coquelicot rely on.
    ok["ClassicalDedekindReals.sig_forall_dec"] = 1
    ok["ClassicalDedekindReals.sig_not_dec"] = 1
    ok["FunctionalExtensionality.functional_extensionality_dep"] = 1
    ok["Classical_Prop.classic"] = 1
    cur = "?"; seen = 0; bad = 0
  }
  /^[ \t]/ || /^$/ { next }                       # continuation lines
  {
    tok = $1; sub(/:$/, "", tok)
    if (tok in thm) { cur = tok; seen++; next }   # output of `Check name.`
    if ($0 == ("Ax" "ioms:") || $0 == "Closed under the global context") next
    if (tok in ok) { used[tok] = 1; next }
    print "check-assumptions: " cur " depends on non-whitelisted: " $0 > "/dev/stderr"
    bad = 1
  }
  END {
    for (a in used) print "  allowed axiom used: " a
    print "  theorems checked: " seen
    if (bad) exit 1
  }' assumptions.log; then
  status=1
fi
checked=$(grep -c '^Print Assumptions ' Assumptions.v)
if [ "$checked" -ne "$count" ]; then
  echo "check-assumptions: Assumptions.v prints $checked theorems, sources define $count" >&2
  status=1
fi
rm -f "$names_file"
if [ "$status" -eq 0 ]; then
  echo "check-assumptions: OK ($count theorems, only real-number axioms)"
fi
exit $status
