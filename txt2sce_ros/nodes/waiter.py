"""A lean wait on one subscription, for lock-step loops.

`SingleThreadedExecutor.spin_once` rebuilds its wait set from every entity of every node on each call (the node's
subscriptions, its parameter services, guard conditions): measured ~260 µs of CPU per call here, on the order of a
whole DDS round trip, and a lock-step loop calls it at least once per step. `SubscriptionWaiter` keeps one wait set
holding just the subscription it waits on and takes every message that arrived, running the subscription's own
callback on each, as the executor would. Everything else of the node (other subscriptions, services) is served by
the executor between runs, as before.
"""

from __future__ import annotations

from typing import Any

from rclpy.executors import ExternalShutdownException
from rclpy.impl.implementation_singleton import rclpy_implementation as _rclpy
from rclpy.node import Node
from rclpy.subscription import Subscription


class SubscriptionWaiter:
    def __init__(self, node: Node, subscription: Subscription) -> None:
        self._context = node.context
        self._sub = subscription
        self._wait_set: Any = None

    def wait(self, timeout_sec: float) -> int:
        """Wait up to `timeout_sec` for messages on the subscription; run its callback on every message taken;
        return how many. Raises ExternalShutdownException when the context was shut down (as spin_once does)."""
        sub = self._sub
        with self._context.handle, sub.handle:
            if self._wait_set is None:
                self._wait_set = _rclpy.WaitSet(1, 0, 0, 0, 0, 0, self._context.handle)
            ws = self._wait_set
            ws.clear_entities()
            ws.add_subscription(sub.handle)
            ws.wait(int(timeout_sec * 1e9))
            if not self._context.ok():
                raise ExternalShutdownException()
            taken = 0
            if ws.get_ready_entities("subscription"):
                while True:
                    info = sub.handle.take_message(sub.msg_type, sub.raw)
                    if info is None:
                        break
                    sub.callback(info[0])
                    taken += 1
        return taken
