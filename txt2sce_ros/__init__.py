"""txt2sce: accident reports → OpenSCENARIO seeds → scenario trees → closed-loop ADS testing.

This package holds the text side, scenario generation, analysis, the road model, the CLI and the generator node.
Nothing imported at package level touches rclpy: the cores run on a plain Python install.
"""

__version__ = "0.1.0"

from .accel import enable as _enable_compiled

_enable_compiled()      # the compiled build of the hot modules, where one matches their source (accel.py)
