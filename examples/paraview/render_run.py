"""Draws a run folder's last state with ParaView, headless:

    xvfb-run -a pvbatch examples/paraview/render_run.py RUN_FOLDER [FIELD] [OUT.png]

The fluid mesh coloured by FIELD (a point or cell array of fluid.pvd: head, pressure,
porosity, permeability; default head), the deformed blocks' outlines over it, and, when the
run wrote them, the fractures as thick lines coloured by aperture. Writes OUT.png (default
RUN_FOLDER/paraview_FIELD.png) and prints what it drew.
"""
import os
import sys

from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetColorTransferFunction, OpenDataFile,
                             ResetCamera, SaveScreenshot, Show)

folder = sys.argv[1]
field = sys.argv[2] if len(sys.argv) > 2 else "head"
png = sys.argv[3] if len(sys.argv) > 3 else os.path.join(folder, f"paraview_{field}.png")

view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [1200, 800]
view.InteractionMode = "2D"
view.OrientationAxesVisibility = 0

fluid = OpenDataFile(os.path.join(folder, "fluid.pvd"))
last = fluid.TimestepValues[-1] if fluid.TimestepValues else 0.0
view.ViewTime = last
fluid_shown = Show(fluid, view)
association = "POINTS" if field in fluid.PointData.keys() else "CELLS"
ColorBy(fluid_shown, (association, field))
if field in ("porosity", "permeability"):
    GetColorTransferFunction(field).UseLogScale = 1
fluid_shown.RescaleTransferFunctionToDataRange(True, False)
fluid_shown.SetScalarBarVisibility(view, True)

blocks_shown = Show(OpenDataFile(os.path.join(folder, "blocks.pvd")), view)
blocks_shown.SetRepresentationType("Wireframe")
blocks_shown.ColorArrayName = ["POINTS", ""]
blocks_shown.AmbientColor = blocks_shown.DiffuseColor = [0.0, 0.0, 0.0]

drawn = ["fluid", "blocks"]
fractures_file = os.path.join(folder, "fractures.pvd")
if os.path.exists(fractures_file):
    fractures_shown = Show(OpenDataFile(fractures_file), view)
    ColorBy(fractures_shown, ("CELLS", "aperture"))
    fractures_shown.LineWidth = 4
    drawn.append("fractures")

ResetCamera(view)
SaveScreenshot(png, view)
print(f"drew {', '.join(drawn)} at time {last:g}, coloured by {field}: {png}")
