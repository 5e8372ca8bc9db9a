"""Helpers shared by the physics packages (input checks); no physics lives here."""
