"""A lean wait on one subscription, for lock-step loops.

`SingleThreadedExecutor.spin_once` rebuilds its wait set from every entity of every node on each call (the node's
subscriptions, its parameter services, guard conditions): measured ~260 µs of CPU per call here, on the order of a
whole DDS round trip, and a lock-step loop calls it at least once per step. `SubscriptionWaiter` keeps one wait set
holding just the subscription it waits on and takes one message per call, running the subscription's own
callback on it, as the executor would. Everything else of the node (other subscriptions, services) is served by
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
        """Wait up to `timeout_sec` for a message on the subscription; take one and run the subscription's
        callback on it; return how many were taken (0 or 1). Messages beyond the first stay queued and make the
        next call return at once: a lock-step loop gets the one it waits for without a second, empty take per
        step. Raises ExternalShutdownException when the context was shut down (as spin_once does)."""
        sub = self._sub
        ctx = self._context.handle
        with ctx, sub.handle:
            if self._wait_set is None:
                self._wait_set = _rclpy.WaitSet(1, 0, 0, 0, 0, 0, ctx)
            ws = self._wait_set
            ws.clear_entities()
            ws.add_subscription(sub.handle)
            ws.wait(int(timeout_sec * 1e9))
            if not ctx.ok():
                raise ExternalShutdownException()
            if not ws.get_ready_entities("subscription"):
                return 0
            info = sub.handle.take_message(sub.msg_type, sub.raw)
        if info is None:
            return 0
        sub.callback(info[0])
        return 1
