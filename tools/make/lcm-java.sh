#!/usr/bin/env bash
# lcm-java.sh DIR JAR TYPE.lcm... - the LCM types as Java classes (lcm-gen
# -j into DIR/src, javac into DIR/classes) packed in JAR, for lcm-spy.
set -e
dir=$1 jar=$2; shift 2
rm -rf "$dir"; mkdir -p "$dir/classes"
echo "lcm-gen -j --jpath $dir/src $*"
lcm-gen -j --jpath "$dir/src" "$@"
javac -nowarn -cp /usr/share/java/lcm.jar -d "$dir/classes" $(find "$dir/src" -name '*.java')
jar cf "$jar" -C "$dir/classes" .
