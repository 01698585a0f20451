"""Thin rclpy adapters of the txt2sce_ros cores."""
