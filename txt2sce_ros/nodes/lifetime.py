"""The start and end of a node process, the same for every node of the graph. A node that cannot start (a bad
parameter, a missing input, a directory it cannot write) ends the process with one line naming the cause and exit
status 2, as the `txt2sce` commands do, never a traceback. Ctrl-C or an external shutdown ends the spin quietly;
then the node's own clean-up, the node is destroyed and the context shut down (if still up).

    rclpy.init(args=args)
    node = build_node(PlannerNode, "planner_node")     # exits with a one-line error if it cannot start
    with node_lifetime(node):
        rclpy.spin(node)
"""

from __future__ import annotations

import os
import sys
from contextlib import contextmanager
from typing import Callable, Iterator, TypeVar

import rclpy
from rclpy.exceptions import ParameterException
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node

from ..errors import Txt2SceError

N = TypeVar("N", bound=Node)


def build_node(factory: Callable[[], N], program: str) -> N:
    """The node `factory` makes. When it cannot start, the process ends here (SystemExit): status 2 with one line
    naming the cause, or quietly with 0 when a stop signal arrived during start-up (the context is shut down, so
    rclpy fails to make the node's handles). Parameters are read and inputs opened in the node's constructor, so
    this is where a user's mistake shows."""
    try:
        return factory()
    except KeyboardInterrupt:
        if rclpy.ok():
            rclpy.shutdown()
        raise SystemExit(0) from None
    except Exception as exc:
        if not rclpy.ok():
            raise SystemExit(0) from None          # stopped while starting: as quiet as a stop while spinning
        if os.environ.get("TXT2SCE_DEBUG") or not isinstance(exc, (Txt2SceError, ParameterException, OSError,
                                                                     ValueError)):
            raise
        msg = f"{exc.filename}: {exc.strerror or exc}" if isinstance(exc, OSError) and exc.filename else str(exc)
        print(f"{program}: error: {msg}", file=sys.stderr)
        rclpy.shutdown()
        raise SystemExit(2) from None


@contextmanager
def node_lifetime(node: N, on_exit: Callable[[], None] | None = None) -> Iterator[N]:
    """Run the body (the spin) for `node`; `on_exit` runs before the node is destroyed (flush, leave an executor)."""
    try:
        yield node
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    except Exception:
        # A stop signal shuts the context down under a running spin, and rclpy may then fail making its wait set
        # ("the given context is not valid") instead of raising ExternalShutdownException: a stop all the same.
        if rclpy.ok():
            raise
    finally:
        if on_exit is not None:
            on_exit()
        node.destroy_node()
        if rclpy.ok():
            rclpy.shutdown()
