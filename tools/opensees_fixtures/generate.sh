#!/usr/bin/env bash
# Regenerates tests/links/fixtures/opensees/*.csv: OpenSees' Steel01, BoucWen and Hysteretic
# materials, compiled from OpenSees' own source at a pinned commit, stepped through the
# displacement history of driver.cpp (tests/links/opensees_fixtures_test.cpp compares pound's laws
# with them).
#
#   tools/opensees_fixtures/generate.sh [output directory]
#
# Only the files the three materials need are taken from OpenSees (git archive of the commit, in a
# temporary directory; nothing of OpenSees is kept in this repository): the materials, their base
# classes (UniaxialMaterial, Material, TaggedObject, MovableObject, DomainComponent) and the
# classes their other methods link against (Vector, Matrix, ID, Information, Response,
# MaterialResponse, OPS_Stream, MapOfTaggedObjects). stubs.cpp stands in for the interpreter's
# argument parsers and LAPACK, which stepping a material never calls.
#
# Environment:
#   OPENSEES_COMMIT   the commit (default below, the one the committed fixtures were made with)
#   OPENSEES_GIT_DIR  a local clone (or bare git directory) that has the commit; without it the
#                     commit is fetched from GitHub (network)
#   CXX               the compiler (default g++)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
out="${1:-$repo/tests/links/fixtures/opensees}"
commit="${OPENSEES_COMMIT:-2890cb36f59b5a707c607c63a831606f325adb7c}"
cxx="${CXX:-g++}"

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

git_dir="${OPENSEES_GIT_DIR:-}"
if [ -z "$git_dir" ]; then
  git_dir="$work/opensees.git"
  git init -q --bare "$git_dir"
  git --git-dir="$git_dir" fetch -q --depth 1 https://github.com/OpenSees/OpenSees.git "$commit"
fi

sources=(
  SRC/material/uniaxial/Steel01.cpp SRC/material/uniaxial/BoucWenMaterial.cpp
  SRC/material/uniaxial/HystereticMaterial.cpp SRC/material/uniaxial/UniaxialMaterial.cpp
  SRC/material/Material.cpp SRC/domain/component/DomainComponent.cpp SRC/tagged/TaggedObject.cpp
  SRC/actor/actor/MovableObject.cpp SRC/matrix/Vector.cpp SRC/matrix/Matrix.cpp SRC/matrix/ID.cpp
  SRC/element/Information.cpp SRC/recorder/response/Response.cpp
  SRC/recorder/response/MaterialResponse.cpp SRC/handler/OPS_Stream.cpp
  SRC/handler/StandardStream.cpp SRC/tagged/storage/MapOfTaggedObjects.cpp
  SRC/tagged/storage/MapOfTaggedObjectsIter.cpp
)
headers=(
  SRC/OPS_Globals.h SRC/classTags.h SRC/actor/actor/MovableObject.h SRC/actor/channel/Channel.h
  SRC/api/GenericDict.h SRC/api/elementAPI.h SRC/domain/component/DomainComponent.h
  SRC/domain/component/Parameter.h SRC/domain/domain/Domain.h SRC/element/Information.h
  SRC/handler/OPS_Stream.h SRC/handler/StandardStream.h SRC/material/Material.h
  SRC/material/uniaxial/BoucWenMaterial.h SRC/material/uniaxial/HystereticMaterial.h
  SRC/material/uniaxial/MaterialState.h SRC/material/uniaxial/Steel01.h
  SRC/material/uniaxial/UniaxialMaterial.h SRC/matrix/ID.h SRC/matrix/Matrix.h SRC/matrix/Vector.h
  SRC/recorder/response/MaterialResponse.h SRC/recorder/response/Response.h
  SRC/tagged/TaggedObject.h SRC/tagged/storage/MapOfTaggedObjects.h
  SRC/tagged/storage/MapOfTaggedObjectsIter.h SRC/tagged/storage/TaggedObjectIter.h
  SRC/tagged/storage/TaggedObjectStorage.h
)
mkdir -p "$work/src"
git --git-dir="$git_dir" archive "$commit" -- "${sources[@]}" "${headers[@]}" |
  tar -x -C "$work/src"

includes=()
for dir in "" actor/actor actor/channel api domain/component domain/domain element handler \
  material material/uniaxial matrix recorder/response tagged tagged/storage; do
  includes+=("-I$work/src/SRC/$dir")
done

# OpenSees' own files are built as they are (-w: their warnings are not ours to fix); no
# -ffast-math or the like, so the arithmetic is what an OpenSees build does.
objects=()
for source in "${sources[@]}"; do
  object="$work/$(basename "$source" .cpp).o"
  nice "$cxx" -std=c++17 -O2 -w "${includes[@]}" -c "$work/src/$source" -o "$object" &
  objects+=("$object")
  # two at a time
  if [ $((${#objects[@]} % 2)) -eq 0 ]; then wait; fi
done
wait
nice "$cxx" -std=c++17 -O2 -Wall -Wextra "${includes[@]/#-I/-isystem}" "$here/driver.cpp" "$here/stubs.cpp" \
  "${objects[@]}" -o "$work/opensees_fixtures"

mkdir -p "$out"
"$work/opensees_fixtures" "$out" "$commit"
