#!/usr/bin/env python3
"""Writes sample-logs/wild/: one short drive (40 s) as five loggers export it, for the
import presets' tests and for trying `gyrodrift import FILE...` and the dashboard's drop.

The drive: 8 s standing, pulling away to 10 m/s, a 90 deg left turn from 20 to 28 s
(course 30 deg -> 300 deg), the gyro with a 0.3 deg/s bias on its yaw axis. Each format
keeps its logger's habits: SensorLog repeats the last GPS fix on every row and has one
duplicated and one out-of-order gyro time; phyphox writes semicolons and decimal commas;
Sensor Logger, PX4 and ROS write one file per sensor. Deterministic (seeded), stdlib only:

    python3 scripts/make-wild-fixtures.py
"""
import math
import os
import random

OUT = os.path.join(os.path.dirname(__file__), "..", "sample-logs", "wild")
DUR = 40.0
BIAS_DPS = 0.3
LAT0, LON0 = 48.137, 11.575
EPOCH = 1_763_892_000  # 2025-11-23 10:00:00 UTC
rng = random.Random(7)


def speed(t):
    return 0.0 if t < 8 else min(10.0, (t - 8) * 2.5)


def yaw_ccw_dps(t):
    return 11.25 if 20 <= t < 28 else 0.0


def course_cw_deg(t):
    """Course after integrating the true yaw rate (exact for the piecewise profile)."""
    turned = 11.25 * min(max(t - 20, 0.0), 8.0)
    return (30.0 - turned) % 360.0


def position(t):
    """Lat, lon by integrating the course at 10 ms steps."""
    n, e, x = 0.0, 0.0, 0.0
    while x < t:
        h = math.radians(course_cw_deg(x))
        n += speed(x) * math.cos(h) * 0.01
        e += speed(x) * math.sin(h) * 0.01
        x += 0.01
    lat = LAT0 + math.degrees(n / 6_371_000)
    lon = LON0 + math.degrees(e / (6_371_000 * math.cos(math.radians(LAT0))))
    return lat, lon


def unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


# The phone stands in a holder, screen to the driver: its +y axis points (nearly) up.
UP_PHONE = unit([0.05, 1.0, 0.1])


def gyro_rad(t, up):
    w = math.radians(yaw_ccw_dps(t) + BIAS_DPS)
    return [w * u + rng.gauss(0, 0.0008) for u in up]


def times(rate_hz):
    return [i / rate_hz for i in range(int(DUR * rate_hz))]


def fixes(rate_hz):
    return [(t, *position(t)) for t in times(rate_hz)]


def write(path, header, rows, sep=",", fmt=lambda v: repr(v)):
    path = os.path.join(OUT, path)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", newline="") as f:
        f.write(sep.join(header) + "\n")
        for r in rows:
            f.write(sep.join(v if isinstance(v, str) else fmt(v) for v in r) + "\n")


def g(x, d=6):
    return f"{x:.{d}f}"


def sensorlog():
    """iOS SensorLog: one CSV, 20 Hz, location repeated on every row (stale between fixes)."""
    gps = fixes(1.0)
    rows = []
    for i, t in enumerate(times(20.0)):
        ft, lat, lon = gps[int(t)]
        v = speed(ft)
        course = course_cw_deg(ft) if v > 0.5 else -1.0
        w = gyro_rad(t, UP_PHONE)
        grav = [-u for u in UP_PHONE]  # CoreMotion gravity points down, in G
        clock = f"2025-11-23 11:{int(t) // 60:02d}:{t % 60:06.3f} +0100"
        rows.append([clock, str(i), g(EPOCH + ft + 0.35, 3), g(lat, 7), g(lon, 7), g(v, 2), g(course, 1),
                     g(1000.0 + t, 5), *(g(x) for x in w), g(1000.0 + t, 5), *(g(x) for x in grav)])
    rows.insert(300, list(rows[300]))  # a duplicated row (same gyro time)
    rows[500][7], rows[501][7] = rows[501][7], rows[500][7]  # two rows out of order by 50 ms
    write("sensorlog/SensorLog.csv", [
        "loggingTime(txt)", "loggingSample(N)", "locationTimestamp_since1970(s)", "locationLatitude(WGS84)",
        "locationLongitude(WGS84)", "locationSpeed(m/s)", "locationCourse(°)", "gyroTimestamp_sinceReboot(s)",
        "gyroRotationX(rad/s)", "gyroRotationY(rad/s)", "gyroRotationZ(rad/s)", "motionTimestamp_sinceReboot(s)",
        "motionGravityX(G)", "motionGravityY(G)", "motionGravityZ(G)"], rows)


def sensor_logger():
    """Sensor Logger (Android): a folder of CSVs, ns epoch times and seconds_elapsed."""
    ns = lambda t: str(int((EPOCH + t) * 1e9))
    xyz = ["time", "seconds_elapsed", "z", "y", "x"]
    gy = [[ns(t), g(t, 4), *(g(x) for x in reversed(gyro_rad(t, UP_PHONE)))] for t in times(25.0)]
    write("sensor-logger/Gyroscope.csv", xyz, gy)
    gr = [[ns(t), g(t, 4), *(g(9.80665 * u + rng.gauss(0, 0.01), 5) for u in reversed(UP_PHONE))] for t in times(25.0)]
    write("sensor-logger/Gravity.csv", xyz, gr)
    acc = [[ns(t), g(t, 4), "0.01", "0.02", "-0.01"] for t in times(25.0)]
    write("sensor-logger/Accelerometer.csv", xyz, acc)
    loc = []
    for t, lat, lon in fixes(1.0):
        v = speed(t)
        b = course_cw_deg(t) if v > 0.5 else 0.0
        loc.append([ns(t), g(t, 4), "2.5", "0.4", "3.1", "4.2", g(v, 2), g(b, 1), "520.3", g(lon, 7), g(lat, 7)])
    write("sensor-logger/Location.csv", ["time", "seconds_elapsed", "bearingAccuracy", "speedAccuracy", "verticalAccuracy",
                                          "horizontalAccuracy", "speed", "bearing", "altitude", "longitude", "latitude"], loc)
    write("sensor-logger/Metadata.csv", ["version", "device name", "recording epoch time", "platform"],
          [["3", "Pixel 7", str(EPOCH * 1000), "android"]])


def phyphox():
    """phyphox's "CSV (semicolon, decimal comma)" export: quoted headers, scientific numbers."""
    num = lambda x: f"{x:.9E}".replace(".", ",")
    q = lambda names: [f'"{n}"' for n in names]
    gy = [[t, *gyro_rad(t, UP_PHONE)] for t in times(25.0)]
    write("phyphox/Gyroscope.csv", q(["Time (s)", "Gyroscope x (rad/s)", "Gyroscope y (rad/s)", "Gyroscope z (rad/s)"]),
          gy, sep=";", fmt=num)
    acc = [[t, *(9.80665 * u + rng.gauss(0, 0.02) for u in UP_PHONE)] for t in times(25.0)]
    write("phyphox/Accelerometer.csv", q(["Time (s)", "Acceleration x (m/s^2)", "Acceleration y (m/s^2)", "Acceleration z (m/s^2)"]),
          acc, sep=";", fmt=num)
    loc = [[t + 0.02, lat, lon, 520.0, speed(t), course_cw_deg(t), 4.0, 3.0] for t, lat, lon in fixes(1.0)]
    write("phyphox/Location.csv", q(["Time (s)", "Latitude (°)", "Longitude (°)", "Height (m)", "Velocity (m/s)", "Direction (°)",
                                     "Horizontal Accuracy (m)", "Vertical Accuracy (m)"]), loc, sep=";", fmt=num)


def px4():
    """pyulog's ulog2csv: FRD body axes, timestamps in microseconds since boot."""
    up_frd = [0.0, 0.0, -1.0]
    us = lambda t: str(int(5_000_000 + t * 1e6))
    imu = [[us(t), *(g(x) for x in gyro_rad(t, up_frd)), "0.02", "0",
            *(g(9.80665 * u + rng.gauss(0, 0.02), 5) for u in up_frd), "0.02", "0"] for t in times(25.0)]
    write("px4/log_12_sensor_combined_0.csv", ["timestamp", "gyro_rad[0]", "gyro_rad[1]", "gyro_rad[2]", "gyro_integral_dt",
                                               "accelerometer_timestamp_relative", "accelerometer_m_s2[0]",
                                               "accelerometer_m_s2[1]", "accelerometer_m_s2[2]",
                                               "accelerometer_integral_dt", "accelerometer_clipping"], imu)
    gps = []
    for t, lat, lon in fixes(5.0):
        v, c = speed(t), math.radians(course_cw_deg(t))
        c = c - 2 * math.pi if c > math.pi else c
        gps.append([us(t), str(int(lat * 1e7)), str(int(lon * 1e7)), "520000", g(v, 3), g(v * math.cos(c), 3),
                    g(v * math.sin(c), 3), "0.0", g(c, 5), "3", "14"])
    write("px4/log_12_vehicle_gps_position_0.csv", ["timestamp", "lat", "lon", "alt", "vel_m_s", "vel_n_m_s", "vel_e_m_s",
                                                    "vel_d_m_s", "cog_rad", "fix_type", "satellites_used"], gps)


def ros():
    """`rostopic echo -p` of sensor_msgs/Imu and NavSatFix: %time in ns, FLU body axes."""
    up_flu = [0.0, 0.0, 1.0]
    ns = lambda t: str(int((EPOCH + t) * 1e9))
    imu = [[ns(t), str(i), ns(t), "imu_link", *(g(x) for x in gyro_rad(t, up_flu)),
            *(g(9.80665 * u + rng.gauss(0, 0.02), 5) for u in up_flu)] for i, t in enumerate(times(25.0))]
    write("ros/imu.csv", ["%time", "field.header.seq", "field.header.stamp", "field.header.frame_id",
                          "field.angular_velocity.x", "field.angular_velocity.y", "field.angular_velocity.z",
                          "field.linear_acceleration.x", "field.linear_acceleration.y", "field.linear_acceleration.z"], imu)
    fix = [[ns(t), ns(t), "0", g(lat, 8), g(lon, 8), "520.0"] for t, lat, lon in fixes(5.0)]
    write("ros/fix.csv", ["%time", "field.header.stamp", "field.status.status", "field.latitude", "field.longitude",
                          "field.altitude"], fix)


if __name__ == "__main__":
    sensorlog()
    sensor_logger()
    phyphox()
    px4()
    ros()
