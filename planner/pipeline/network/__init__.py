"""Registration: target candidates and their sight lines, the links between scans
(targets, cloud-to-cloud, hybrid), the network's layout and adjustment, control points and
the traverse, and the seams that tie district blocks together.

May import the inputs, geometry and evaluation rooms.
"""
