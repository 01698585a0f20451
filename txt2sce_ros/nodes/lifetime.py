"""The end of a node process, the same for every node of the graph: Ctrl-C or an external shutdown ends the spin
quietly; then the node's own clean-up, the node is destroyed and the context shut down (if still up).

    rclpy.init(args=args)
    with node_lifetime(PlannerNode()) as node:
        rclpy.spin(node)
"""

from __future__ import annotations

from contextlib import contextmanager
from typing import Callable, Iterator, TypeVar

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node

N = TypeVar("N", bound=Node)


@contextmanager
def node_lifetime(node: N, on_exit: Callable[[], None] | None = None) -> Iterator[N]:
    """Run the body (the spin) for `node`; `on_exit` runs before the node is destroyed (flush, leave an executor)."""
    try:
        yield node
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        if on_exit is not None:
            on_exit()
        node.destroy_node()
        if rclpy.ok():
            rclpy.shutdown()
