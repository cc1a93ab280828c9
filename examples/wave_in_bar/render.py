# Renders wave_in_bar.e with ParaView (Debian: python3-paraview, xvfb):
#   PYTHONPATH=/usr/lib/python3/dist-packages xvfb-run -a pvbatch render.py
# Writes wave.png: the bar coloured by the x velocity at the 7th output record, where the
# pulse has run about 40% of the bar.
from paraview.simple import *

reader = OpenDataFile('wave_in_bar.e')
reader.UpdatePipeline()
print('point arrays:', reader.PointData.keys(), 'cell arrays:', reader.CellData.keys())
print('records:', len(reader.TimestepValues))
view = GetActiveViewOrCreate('RenderView')
view.ViewSize = [800, 300]
display = Show(reader, view)
display.SetRepresentationType('Points')
display.PointSize = 6
ColorBy(display, ('POINTS', 'Velocity', 'X'))
GetAnimationScene().AnimationTime = reader.TimestepValues[6]
view.Update()
display.RescaleTransferFunctionToDataRange(False, True)
ResetCamera()
SaveScreenshot('wave.png', view)
