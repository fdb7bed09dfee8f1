# Expected runway thresholds for tests/command/test_runways.cpp, computed with
# BlueSky's formulas (navdatabase/loadnavdata_txt.py: thresholds, thrpoints;
# REARTH_INV = 1.56961231e-7) transcribed here:
#   /usr/bin/python3 tests/data/runways/thresholds.py
import math
REARTH_INV = 1.56961231e-7
def thresholds(lat1, lon1, lat2, lon2, offset):
    lat1, lon1, lat2, lon2 = map(math.radians, (lat1, lon1, lat2, lon2))
    d = offset * REARTH_INV
    dl = lon2 - lon1
    b = math.atan2(math.sin(dl) * math.cos(lat2),
                   math.cos(lat1) * math.sin(lat2) - math.sin(lat1) * math.cos(lat2) * math.cos(dl))
    b = math.radians((math.degrees(b) + 360) % 360)
    lt = math.asin(math.sin(lat1) * math.cos(d) + math.cos(lat1) * math.sin(d) * math.cos(b))
    ln = lon1 + math.atan2(math.sin(b) * math.sin(d) * math.cos(lat1), math.cos(d) - math.sin(lat1) * math.sin(lt))
    return math.degrees(lt), math.degrees(ln), math.degrees(b)
for name, row in (("EHEH 03", (51.4423, 5.3631, 51.4641, 5.3947, 150.0)),
                  ("EHEH 21", (51.4641, 5.3947, 51.4423, 5.3631, 0.0)),
                  ("EHAM 18L", (52.3214, 4.78, 52.29, 4.7773, 0.0)),
                  ("EHAM 36R", (52.29, 4.7773, 52.3214, 4.78, 400.0))):
    print(name, "%.9f %.9f %.9f" % thresholds(*row))
