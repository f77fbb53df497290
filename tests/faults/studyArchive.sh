#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# dpmStudy export and import against hostile or broken archives and
# studies. Nothing is run: a study "src" holds one summary case made by
# hand (w 0.5 at 1 bar, seed 1: the template's dictionaries, an
# archivedCase, a log head and small tables); its export is the base that
# the archives here are made from with Python's tarfile.
#   1. an archive's members: a setuid file, a mode-0666 caseSettings, a
#      file beyond the size bounds, a link, a file outside the layout of a
#      summary study ('..', an absolute path, another folder): refused
#      naming the member, or (a dictionary) imported with this process's
#      modes; a refused import changes nothing and writes nothing outside;
#   2. export through a symbolic link at its archive's name or at the old
#      <archive>.partial: the files the links point to stay as they were;
#   3. a symbolic link inside a case (a dictionary, the log, a table
#      folder): export and import of the study directory refuse it,
#      naming it, and carry nothing of the file it points to;
#   4. a summary case without its log, with time nan or without its time
#      line, with a time or wSmall that is no number: refused naming the
#      member and the entry (no traceback);
#   5. an import onto a case name that is a dangling link: refused naming
#      it, nothing left behind;
#   6. import with pictures on, and results of the merged study: finish,
#      the summary case's snapshot left out with a note;
#   7. an import refused for another dictionary names the differing entry,
#      not the file's banner.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/faults/summaryFunctions"
cd "$workDir" || fail "cd"
umask 022
python=/usr/bin/python3
case1=w0.50_1bar_seed1
noTraceback() { ! grep -q "Traceback" "$1" || { cat "$1"; fail "$2: a traceback"; }; }

# The study src: one summary case made by hand
summaryCaseDictionaries src $case1 && markSummaryCase src/$case1 || fail "the summary case"
mkdir -p src/$case1/postProcessing/bedStatistics/0
printf '# Time bedHeight\n0.05 0.1\n' > src/$case1/postProcessing/bedStatistics/0/bed.dat

dpmStudy export src base.tar.gz > log.base 2>&1 || { cat log.base; fail "export of src"; }
grep -q "export: 1 finished cases of src -> base.tar.gz" log.base || { cat log.base; fail "the export's line"; }
dpmStudy import clean base.tar.gz -noPictures > log.clean 2>&1 || { cat log.clean; fail "import of base.tar.gz"; }
[ -f clean/$case1/constant/archivedCase ] || fail "no summary case imported from base.tar.gz"
echo "ok   the base archive exports and imports"

# craft <archive> <python>: base.tar.gz rewritten into <archive>, its
# members (base's names, src/...) edited by the Python statements first:
#   add(name, data, mode=0o644, kind=tarfile.REGTYPE, link="", size=None)
#   drop(name), text(name, new content), rename(old prefix, new prefix);
#   members: the list of [TarInfo, bytes]
craft()
{
    $python - "$@" <<'EOF' || fail "craft $1"
import io, sys, tarfile
out, code = sys.argv[1:3]
members = []
with tarfile.open("base.tar.gz") as tar:
    for m in tar:
        members.append([m, tar.extractfile(m).read() if m.isfile() else b""])
def add(name, data=b"", mode=0o644, kind=tarfile.REGTYPE, link="", size=None):
    m = tarfile.TarInfo(name)
    m.mode, m.type, m.linkname = mode, kind, link
    m.size = len(data) if size is None else size
    members.append([m, data])
def drop(name):
    members[:] = [e for e in members if e[0].name != name]
def text(name, content):
    for e in members:
        if e[0].name == name:
            e[1] = content.encode()
def rename(old, new):
    for e in members:
        if e[0].name.startswith(old):
            e[0].name = new + e[0].name[len(old):]
exec(code)
class Zeros(io.RawIOBase):
    """size zero bytes (a member far larger than the archive)"""
    def __init__(self, size): self.left = size
    def readable(self): return True
    def readinto(self, b):
        n = min(len(b), self.left); b[:n] = bytes(n); self.left -= n; return n
with tarfile.open(out, "w:gz", compresslevel=1) as tar:
    for m, data in members:
        if m.isfile():
            m.size = m.size if data == b"" and m.size else len(data)
            tar.addfile(m, io.BufferedReader(Zeros(m.size)) if data == b"" else io.BytesIO(data))
        else:
            tar.addfile(m)
EOF
}

# refused <archive> <pattern> <what>: import of archive into a copy of
# clean fails with a message matching pattern, no traceback, the study as
# it was, nothing of it left in the study
refused()
{
    local archive="$1" pattern="$2" what="$3"
    rm -rf D && cp -a clean D
    dpmStudy import D "$archive" -noPictures > log.refused 2>&1 \
        && { cat log.refused; fail "$what: imported"; }
    noTraceback log.refused "$what"
    grep -qE "$pattern" log.refused || { cat log.refused; fail "$what: no message '$pattern'"; }
    diff -r clean D > /dev/null || { diff -r clean D | head; fail "$what: the refused import changed the study"; }
    echo "ok   $what: $(grep -m1 -E "$pattern" log.refused | cut -c1-200)"
}
s=src/$case1          # the case's members in base.tar.gz

echo "1. an archive's members: modes, size bounds, links and the layout"
# Into a new study: its caseSettings world-writable, a dictionary setuid,
# the folders' modes 0777; imported with this process's modes
craft modes.tar.gz "for e in members:
    if e[0].name.endswith('constant/caseSettings'): e[0].mode = 0o666
    if e[0].isdir(): e[0].mode = 0o777
add('$s/constant/sh', b'#!/bin/sh\n', mode=0o6755)"
dpmStudy import M modes.tar.gz -noPictures > log.modes 2>&1 || { cat log.modes; fail "import of modes.tar.gz"; }
[ -f M/$case1/constant/sh ] || fail "the archive's dictionary constant/sh was not imported"
bad=$(find M \( -perm /6000 -o -perm -0002 \) ! -type l)
[ -z "$bad" ] || { ls -ld $bad; fail "setuid, setgid or world-writable files imported: $bad"; }
[ "$(stat -c %a M/$case1/constant/caseSettings)" = 644 ] \
    || fail "caseSettings imported with mode $(stat -c %a M/$case1/constant/caseSettings), not 644 (umask 022)"
echo "ok   a setuid dictionary and a mode-0666 caseSettings imported with mode 644"

craft setuid.tar.gz "add('$s/postProcessing/laceyIndex/0/sh', b'#!/bin/sh\n', mode=0o4755)"
refused setuid.tar.gz "member $s/postProcessing/laceyIndex/0/sh is no part of a study archive" "a setuid file in a table folder"
craft bin.tar.gz "add('$s/bin/sh', b'#!/bin/sh\n', mode=0o4755)"
refused bin.tar.gz "member $s/bin/sh is no part of a study archive" "a file outside a summary case's folders"
craft big.tar.gz "add('$s/postProcessing/laceyIndex/0/zeros.dat', size=65 << 20)"
[ "$(stat -c %s big.tar.gz)" -lt 1000000 ] || fail "big.tar.gz is not small"
refused big.tar.gz "member $s/postProcessing/laceyIndex/0/zeros.dat is 68157440 bytes; a study archive unpacks at most 64 MiB a file, 1024 MiB in all" "a file of 65 MiB"
craft total.tar.gz "for i in range(17): add('$s/postProcessing/laceyIndex/0/zeros%d.dat' % i, size=63 << 20)"
refused total.tar.gz "too large at member $s/postProcessing/laceyIndex/0/zeros16.dat; a study archive unpacks at most" "17 files of 63 MiB"
dpmStudy -h | tr '\n' ' ' | grep -q "64 MiB a file, 1024 MiB in all and 100000 members" \
    || fail "dpmStudy -h does not state the archive's bounds"
craft link.tar.gz "add('$s/constant/passwd', kind=tarfile.SYMTYPE, link='/etc/passwd')"
refused link.tar.gz "member $s/constant/passwd is a link \(to /etc/passwd\)" "a symbolic link"
craft hardlink.tar.gz "add('$s/constant/hard', kind=tarfile.LNKTYPE, link='$s/constant/g')"
refused hardlink.tar.gz "member $s/constant/hard is a link" "a hard link"
craft dotdot.tar.gz "add('src/../escaped', b'x')"
refused dotdot.tar.gz "member src/../escaped is no part of a study archive" "a name with .."
craft absolute.tar.gz "add('$workDir/absolute', b'x')"
refused absolute.tar.gz "member $workDir/absolute is no part of a study archive" "an absolute name"
[ ! -e escaped ] && [ ! -e absolute ] || fail "a refused archive wrote outside the study"
craft fifo.tar.gz "add('$s/constant/fifo', kind=tarfile.FIFOTYPE)"
refused fifo.tar.gz "member $s/constant/fifo is neither a file nor a directory" "a FIFO"

echo "2. export through a symbolic link"
echo precious > precious1 && echo precious > precious2
ln -s "$PWD/precious1" out.tar.gz.partial
ln -s "$PWD/precious2" linked.tar.gz
for archive in out.tar.gz linked.tar.gz
do
    dpmStudy export src $archive > log.export 2>&1 || { cat log.export; fail "export $archive"; }
    [ -f $archive ] && [ ! -L $archive ] || fail "$archive is not a file of its own"
    tar -tzf $archive > /dev/null || fail "$archive is no archive"
done
[ "$(cat precious1)" = precious ] || fail "export wrote through the link out.tar.gz.partial"
[ "$(cat precious2)" = precious ] || fail "export wrote through the link at its archive's name"
[ -z "$(ls -A | grep -E '^\.(out|linked)\.tar\.gz')" ] || fail "temporary files left: $(ls -A | grep tar.gz)"
echo "ok   the files links at the archive's name and at <archive>.partial point to are unchanged"

echo "3. a symbolic link inside a case"
echo "SECRET outside the study" > secret
mkdir -p outsideTables/0 && cp src/$case1/postProcessing/laceyIndex/0/* outsideTables/0/
echo "SECRET" >> outsideTables/0/laceyIndex.dat
n=0
for link in constant/gasProperties log.dpmFoam2D postProcessing/laceyIndex
do
    n=$((n + 1))
    rm -rf L$n && cp -a src L$n
    rm -rf L$n/$case1/$link
    if [ "$link" = postProcessing/laceyIndex ]
    then
        ln -s "$PWD/outsideTables" L$n/$case1/$link
    else
        ln -s "$PWD/secret" L$n/$case1/$link
    fi
    dpmStudy export L$n L$n.tar.gz > log.exportL$n 2>&1 && fail "export of a case with a linked $link"
    noTraceback log.exportL$n "export, a linked $link"
    grep -q "L$n/$case1/$link is a symbolic link" log.exportL$n || { cat log.exportL$n; fail "export: no message naming the link $link"; }
    [ ! -e L$n.tar.gz ] || fail "export of a case with a linked $link wrote an archive"
    dpmStudy import I$n L$n -noPictures > log.importL$n 2>&1 && fail "import of a case with a linked $link"
    noTraceback log.importL$n "import, a linked $link"
    grep -q "L$n/$case1/$link is a symbolic link" log.importL$n || { cat log.importL$n; fail "import: no message naming the link $link"; }
    ! grep -rq SECRET I$n 2>/dev/null || fail "import carried the file the link $link points to"
    echo "ok   $link: $(grep -m1 "is a symbolic link" log.importL$n | sed 's/^ *//' | cut -c1-200)"
done

echo "4. summary cases that are no finished run, or hold no numbers"
craft nolog.tar.gz "drop('$s/log.dpmFoam2D')"
refused nolog.tar.gz "nolog.tar.gz: $s: a summary case of an unfinished run: no log.dpmFoam2D" "no log.dpmFoam2D"
craft nan.tar.gz "text('$s/constant/archivedCase', 'time nan\n')"
refused nan.tar.gz "nan.tar.gz: $s/constant/archivedCase: time nan is not a time" "time nan"
craft notime.tar.gz "text('$s/constant/archivedCase', 'from elsewhere\n')"
refused notime.tar.gz "notime.tar.gz: $s/constant/archivedCase: no 'time <latest time of the run>' line" "no time line"
craft abc.tar.gz "text('$s/constant/archivedCase', 'time abc\n')"
refused abc.tar.gz "abc.tar.gz: $s/constant/archivedCase: time 'abc' is not a number" "time abc"
craft wabc.tar.gz "
for e in members:
    if e[0].name.endswith('constant/caseSettings'):
        e[1] = e[1].replace(b'wSmall          0.5;', b'wSmall          abc;')"
refused wabc.tar.gz "wabc.tar.gz: $s/constant/caseSettings: wSmall 'abc' is not a number \(a mass fraction in \[0, 1\] wanted\)" "wSmall abc"

echo "5. an import onto a case name that is a dangling link"
craft seed2.tar.gz "rename('$s', 'src/w0.50_1bar_seed2')"
rm -rf D && cp -a clean D && ln -s "$PWD/nowhere" D/w0.50_1bar_seed2
dpmStudy import D seed2.tar.gz -noPictures > log.dangling 2>&1 && { cat log.dangling; fail "imported onto a dangling link"; }
noTraceback log.dangling "a dangling link"
grep -q "D/w0.50_1bar_seed2 is a symbolic link (to $PWD/nowhere), no case of the study: remove or rename it" log.dangling \
    || { cat log.dangling; fail "no message naming the dangling link"; }
[ -z "$(ls -A D | grep importing)" ] || fail "left behind: $(ls -A D | grep importing)"
[ ! -e nowhere ] || fail "written where the dangling link points"
echo "ok   $(grep -m1 "is a symbolic link" log.dangling | sed 's/^ *//' | cut -c1-200)"

echo "6. pictures of a study with summary cases"
rm -rf P && cp -a clean P
dpmStudy import P seed2.tar.gz > log.pictures 2>&1 || { cat log.pictures; fail "import with pictures"; }
noTraceback log.pictures "import with pictures"
grep -q "results: no snapshot of $case1: a summary case (imported), without particle files" log.pictures \
    || { cat log.pictures; fail "no note on the summary case's snapshot"; }
dpmStudy results P > log.results 2>&1 || { cat log.results; fail "results of a merged study"; }
echo "ok   import with pictures and results: $(grep -m1 "no snapshot" log.results)"

echo "7. another dictionary: the differing entry named, not the banner"
craft dictionary.tar.gz "rename('$s', 'src/w0.50_1bar_seed2')
for e in members:
    if e[0].name.endswith('constant/gasProperties'):
        e[1] = e[1].replace(b'| dpmFoam2D    ', b'| dpmFoam2D 2.0').replace(b'1.75e-5;', b'1.9e-5; ')"
refused dictionary.tar.gz "w0.50_1bar_seed2: its dictionaries differ from $case1's: constant/gasProperties: [-+]viscosity +1.(75|9)e-5;" "another gasProperties"
pass "hostile and broken archives and studies are refused, naming the member, link or entry; imports take this process's modes and stay within the size bounds; pictures skip summary cases"
