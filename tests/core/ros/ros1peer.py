#!/usr/bin/python3
"""A ROS 1 node that is not ours: rospy, as Debian ships it, for the tests of HATPIC's ROS 1 side.

Subscribes and publishes the topics named on the command line and talks JSON lines:

  stdout  {"event": "ready", "uri": URI}             once the node is up
          {"topic": T, "callerid": C, "msg": {...}}  every message received
          {"event": "connections", "topic": T, "count": N}  a publisher's subscribers changed
          {"event": "nodelay", "topic": T, "values": [0|1, ...]}  answer to "nodelay T"
          {"event": "lookup", "node": N, "uri": URI|null}          answer to "lookup N"
          {"event": "topics", "list": [[T, TYPE], ...]}            answer to "topics"
  stdin   set T JSON    publish JSON on T --rate times a second from now on
          once T JSON   publish JSON on T once
          stop T        stop publishing T
          nodelay T | lookup N | topics | quit

A message in JSON is its fields as nested objects ({"wrench": {"force": {"z": 0.5}}}); a missing
field keeps its default, NaN and Infinity are accepted. Non-finite numbers go out as strings.
"""
import argparse
import json
import math
import socket
import sys
import threading

import rosgraph
import rospy
from geometry_msgs.msg import PoseStamped, Twist, TwistStamped, Wrench, WrenchStamped
from sensor_msgs.msg import Imu, JointState
from std_msgs.msg import Bool, String, UInt8

TYPES = {cls._type: cls for cls in (JointState, TwistStamped, Twist, PoseStamped, WrenchStamped, Wrench, Bool, Imu,
                                    String, UInt8)}
out_lock = threading.Lock()


def say(obj):
    with out_lock:
        sys.stdout.write(json.dumps(obj) + "\n")
        sys.stdout.flush()


def to_json(value):
    if hasattr(value, "__slots__"):
        if isinstance(value, (rospy.Time, rospy.Duration)):
            return {"secs": value.secs, "nsecs": value.nsecs}
        return {slot: to_json(getattr(value, slot)) for slot in value.__slots__}
    if isinstance(value, (list, tuple)):
        return [to_json(v) for v in value]
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)
    return value


def fill(msg, fields):
    for key, value in fields.items():
        current = getattr(msg, key)
        if isinstance(value, dict):
            fill(current, value)
        elif isinstance(current, float):
            setattr(msg, key, float(value))
        else:
            setattr(msg, key, value)
    return msg


def topic_type(spec):
    topic, _, name = spec.partition("=")
    if name not in TYPES:
        sys.exit("ros1peer: unknown type %r (one of %s)" % (name, ", ".join(TYPES)))
    return topic, TYPES[name]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--name", default="hatpic_test_peer")
    parser.add_argument("--sub", action="append", default=[], metavar="TOPIC=TYPE")
    parser.add_argument("--pub", action="append", default=[], metavar="TOPIC=TYPE")
    parser.add_argument("--rate", type=float, default=50.0)
    parser.add_argument("--nodelay", action="store_true", help="subscriptions ask for TCP_NODELAY")
    args = parser.parse_args()

    rospy.init_node(args.name, disable_signals=True)
    for spec in args.sub:
        topic, cls = topic_type(spec)

        def received(msg, topic=topic):
            say({"topic": topic, "callerid": msg._connection_header.get("callerid"),
                 "msg": to_json(msg)})

        rospy.Subscriber(topic, cls, received, tcp_nodelay=args.nodelay)
    publishers = {}
    for spec in args.pub:
        topic, cls = topic_type(spec)
        publishers[topic] = (rospy.Publisher(topic, cls, queue_size=10), cls)

    repeating = {}
    lock = threading.Lock()
    done = threading.Event()

    def publish_loop():
        counts = {}
        period = 1.0 / args.rate
        while not done.wait(period):
            with lock:
                items = list(repeating.items())
            for topic, msg in items:
                publishers[topic][0].publish(msg)
            for topic, (pub, _) in publishers.items():
                n = pub.get_num_connections()
                if counts.get(topic) != n:
                    counts[topic] = n
                    say({"event": "connections", "topic": topic, "count": n})

    threading.Thread(target=publish_loop, daemon=True).start()
    say({"event": "ready", "uri": rospy.get_node_uri()})

    master = rosgraph.Master(rospy.get_name())
    for line in sys.stdin:
        words = line.strip().split(" ", 2)
        command = words[0] if words else ""
        if command in ("set", "once") and len(words) == 3 and words[1] in publishers:
            pub, cls = publishers[words[1]]
            msg = fill(cls(), json.loads(words[2]))
            if command == "once":
                pub.publish(msg)
            else:
                with lock:
                    repeating[words[1]] = msg
        elif command == "stop" and len(words) == 2:
            with lock:
                repeating.pop(words[1], None)
        elif command == "nodelay" and len(words) == 2 and words[1] in publishers:
            impl = publishers[words[1]][0].impl
            values = [c.socket.getsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY)
                      for c in impl.connections if getattr(c, "socket", None)]
            say({"event": "nodelay", "topic": words[1], "values": values})
        elif command == "lookup" and len(words) == 2:
            try:
                uri = master.lookupNode(words[1])
            except rosgraph.MasterError:
                uri = None
            say({"event": "lookup", "node": words[1], "uri": uri})
        elif command == "topics":
            say({"event": "topics", "list": master.getPublishedTopics("/")})
        elif command == "quit":
            break
        elif command:
            say({"event": "error", "line": line.strip()})
    done.set()
    rospy.signal_shutdown("quit")


if __name__ == "__main__":
    main()
