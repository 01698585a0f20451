"""The Storyboard: Init, Story/Act/ManeuverGroup/Maneuver/Event elements with the ASAM life cycle."""
