#!/bin/sh
# The baseline of the launch benchmark: union.launch's four nodes started from a plain shell,
# each with the same ROS arguments the launcher gives them. Ctrl-C stops them all: with
# SIGTERM, because a non-interactive shell starts background jobs with SIGINT ignored.
py=${PYTHON:-python3}
pids=""
for ns in ns1 ns2; do
  for node in publisher subscriber; do
    "$py" -m ros_tutorials_topic.$node --ros-args -r __node:=topic_$node -r __ns:=/$ns &
    pids="$pids $!"
  done
done
trap 'kill -TERM $pids; wait' INT TERM
wait
