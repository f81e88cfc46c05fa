# ParaView state of an fddem run, written into every run directory by `fddem run`
# (the source is python/fddem/paraview_state.py in fddem's repository).
#
#   paraview --script=open_in_paraview.py     the ParaView window with this run loaded
#   pvpython open_in_paraview.py              the same without a window
#
# Both leave the view at the last frame and save it as open_in_paraview.png beside this file.
# It opens fields.pvd (the flow, coloured by |u|; in 3D the box outline and the mid-plane z)
# and particles.pvd (a sphere of the body's radius at each centre, from the "radius" array; in
# 2D the spheres centred on the plane show as the disks), with time running over the frames.
import os

from paraview.simple import (
    ColorBy, GetActiveCamera, GetActiveViewOrCreate, GetAnimationScene, GetColorTransferFunction,
    Glyph, PVDReader, Render, ResetCamera, SaveScreenshot, Show, Slice)

HERE = os.path.dirname(os.path.abspath(__file__))


def show_fields(view):
    fields = PVDReader(registrationName="fields", FileName=os.path.join(HERE, "fields.pvd"))
    fields.UpdatePipeline()
    bounds = fields.GetDataInformation().GetBounds()
    is_3d = bounds[5] > bounds[4]
    shown = fields
    if is_3d:
        outline = Show(fields, view)
        outline.SetRepresentationType("Outline")
        shown = Slice(registrationName="mid-plane z", Input=fields)
        shown.SliceType = "Plane"
        shown.SliceType.Origin = [0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
                                  0.5 * (bounds[4] + bounds[5])]
        shown.SliceType.Normal = [0.0, 0.0, 1.0]
    display = Show(shown, view)
    ColorBy(display, ("CELLS", "velocity", "Magnitude"))
    lut = GetColorTransferFunction("velocity")
    lut.ApplyPreset("Viridis (matplotlib)", True)
    display.RescaleTransferFunctionToDataRange(True, False)
    display.SetScalarBarVisibility(view, True)
    return is_3d


def show_bodies(view):
    path = os.path.join(HERE, "particles.pvd")
    if not os.path.exists(path):
        return
    bodies = PVDReader(registrationName="particles", FileName=path)
    spheres = Glyph(registrationName="bodies", Input=bodies, GlyphType="Sphere")
    spheres.ScaleArray = ["POINTS", "radius"]
    spheres.ScaleFactor = 2.0  # the unit Sphere glyph has radius 0.5: scaled by 2 r, radius r
    spheres.GlyphMode = "All Points"
    spheres.GlyphType.ThetaResolution = 48
    spheres.GlyphType.PhiResolution = 24
    display = Show(spheres, view)
    ColorBy(display, None)
    display.AmbientColor = display.DiffuseColor = [0.92, 0.92, 0.92]


def main():
    view = GetActiveViewOrCreate("RenderView")
    is_3d = show_fields(view)
    show_bodies(view)
    GetAnimationScene().UpdateAnimationUsingDataTimeSteps()
    if not is_3d:
        view.InteractionMode = "2D"
        camera = GetActiveCamera()
        camera.SetViewUp(0.0, 1.0, 0.0)
    ResetCamera(view)
    Render(view)
    return view


view = main()
GetAnimationScene().AnimationTime = GetAnimationScene().EndTime
SaveScreenshot(os.path.join(HERE, "open_in_paraview.png"), view, ImageResolution=[1200, 900])
