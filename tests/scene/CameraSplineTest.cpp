// Camera path playback: the spline passes through every key, is C1 at keys
// (also at a closed loop's seam), keeps constant speed when asked, and never
// flips its orientation.
#include "lpv/scene/CameraSpline.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_access.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

using namespace lpv::scene;

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

glm::quat yaw(float radians) {
    return glm::angleAxis(radians, glm::vec3(0, 1, 0));
}

// Angle of the rotation between two orientations (q and -q are the same);
// atan2 rather than acos(dot), which loses small angles in float.
float rotationAngle(const glm::quat& a, const glm::quat& b) {
    const glm::quat r = glm::conjugate(glm::normalize(a)) * glm::normalize(b);
    return 2.0f * std::atan2(glm::length(glm::vec3(r.x, r.y, r.z)), std::abs(r.w));
}

// The sign a matrix-to-quaternion conversion picks (w >= 0), which puts
// keys more than 180 degrees from identity in the other hemisphere.
glm::quat canonical(const glm::quat& q) {
    return q.w < 0.0f ? -q : q;
}

// Uneven times and distances, turning orientations, changing field of view.
CameraPath windingPath(bool closed) {
    CameraPath p;
    p.name = "winding";
    p.closed = closed;
    p.keyframes = {
        {0.0f, {0, 1, 0}, yaw(0.0f), 0.8f},
        {1.0f, {4, 1.5f, 1}, yaw(0.6f) * glm::angleAxis(0.2f, glm::vec3(1, 0, 0)), 0.9f},
        {1.5f, {5, 2, 4}, yaw(1.4f), 0.7f},
        {3.5f, {1, 1, 6}, yaw(2.5f) * glm::angleAxis(-0.3f, glm::vec3(1, 0, 0)), 1.1f},
        {4.0f, {-2, 0.5f, 3}, yaw(3.3f), 0.75f},
    };
    return p;
}

glm::vec3 velocityLeft(const CameraSpline& s, float t, float h) {
    return (s.sample(t).position - s.sample(t - h).position) / h;
}
glm::vec3 velocityRight(const CameraSpline& s, float t, float h) {
    return (s.sample(t + h).position - s.sample(t).position) / h;
}

// Body-frame angular velocity (rad/s) from two nearby samples.
glm::vec3 angularVelocity(const glm::quat& a, const glm::quat& b, float h) {
    glm::quat r = glm::conjugate(a) * b;
    if (r.w < 0.0f)
        r = -r;
    const glm::vec3 v(r.x, r.y, r.z);
    const float s = glm::length(v);
    return s > 0.0f ? v * (2.0f * std::atan2(s, r.w) / s / h) : glm::vec3(0.0f);
}

void expectSameDirectionAndSpeed(const glm::vec3& left, const glm::vec3& right, float tolerance,
                                 const char* what, float t) {
    const float scale = std::max({glm::length(left), glm::length(right), 1.0f});
    EXPECT_LT(glm::length(left - right), tolerance * scale)
        << what << " at t=" << t << ": left (" << left.x << ", " << left.y << ", " << left.z << ") right ("
        << right.x << ", " << right.y << ", " << right.z << ")";
}

} // namespace

TEST(CameraSpline, PassesThroughEveryKeyOfAnOpenPath) {
    const CameraPath path = windingPath(false);
    const CameraSpline spline(path);
    EXPECT_EQ(spline.duration(), 4.0f);
    for (const CameraKeyframe& key : path.keyframes) {
        const CameraKeyframe k = spline.sample(key.time);
        EXPECT_EQ(k.position, key.position) << "t=" << key.time;
        EXPECT_LT(rotationAngle(k.orientation, key.orientation), 1e-3f) << "t=" << key.time;
        EXPECT_EQ(k.fovY, key.fovY) << "t=" << key.time;
        EXPECT_EQ(k.time, key.time);
    }
}

TEST(CameraSpline, PassesThroughEveryKeyOfAClosedPath) {
    const CameraPath path = windingPath(true);
    const CameraSpline spline(path);
    // Four segments averaging 1 s, and the closing one lasts as long.
    EXPECT_FLOAT_EQ(spline.duration(), 5.0f);
    for (const CameraKeyframe& key : path.keyframes) {
        const CameraKeyframe k = spline.sample(key.time);
        EXPECT_EQ(k.position, key.position) << "t=" << key.time;
        EXPECT_LT(rotationAngle(k.orientation, key.orientation), 1e-3f) << "t=" << key.time;
        EXPECT_EQ(k.fovY, key.fovY);
    }
    // One period later, the first key again.
    EXPECT_EQ(spline.sample(spline.endTime()).position, path.keyframes.front().position);
    EXPECT_EQ(spline.sample(2.0f * spline.duration()).position, path.keyframes.front().position);
}

TEST(CameraSpline, ConstantSpeedStillPassesThroughEveryKeyPosition) {
    CameraPath path = windingPath(false);
    path.constantSpeed = true;
    const CameraSpline spline(path);
    for (const CameraKeyframe& key : path.keyframes) {
        float nearest = 1e9f;
        for (int i = 0; i <= 4000; ++i)
            nearest = std::min(nearest, glm::distance(spline.sample(spline.duration() * i / 4000.0f).position,
                                                      key.position));
        EXPECT_LT(nearest, spline.length() / 4000.0f) << "key at t=" << key.time;
    }
    EXPECT_EQ(spline.sample(0.0f).position, path.keyframes.front().position);
    EXPECT_EQ(spline.sample(spline.endTime()).position, path.keyframes.back().position);
}

TEST(CameraSpline, FirstDerivativeIsContinuousAtKeys) {
    const CameraSpline spline(windingPath(false));
    constexpr float h = 1e-3f;
    for (const float t : {1.0f, 1.5f, 3.5f}) {
        expectSameDirectionAndSpeed(velocityLeft(spline, t, h), velocityRight(spline, t, h), 0.02f,
                                    "velocity", t);
        const glm::quat before = spline.sample(t - h).orientation;
        const glm::quat at = spline.sample(t).orientation;
        const glm::quat after = spline.sample(t + h).orientation;
        expectSameDirectionAndSpeed(angularVelocity(before, at, h), angularVelocity(at, after, h), 0.02f,
                                    "angular velocity", t);
        const float fovLeft = (spline.sample(t).fovY - spline.sample(t - h).fovY) / h;
        const float fovRight = (spline.sample(t + h).fovY - spline.sample(t).fovY) / h;
        EXPECT_NEAR(fovLeft, fovRight, 0.02f) << "fov rate at t=" << t;
    }
}

TEST(CameraSpline, TheDerivativeTestNoticesAKink) {
    // The same check on a path that turns a corner at constant speed fails,
    // so the test above can tell a smooth key from a kinked one.
    CameraPath corner;
    corner.keyframes = {{0.0f, {0, 0, 0}, yaw(0), 0.8f}, {1.0f, {1, 0, 0}, yaw(0), 0.8f}};
    const CameraSpline a(corner);
    const glm::vec3 left = velocityLeft(a, 1.0f, 1e-3f);
    const glm::vec3 turned(left.z, left.y, left.x); // 90 degrees off
    EXPECT_GT(glm::length(left - turned), 0.02f * glm::length(left));
}

TEST(CameraSpline, ClosedLoopIsC1AtTheSeam) {
    const CameraSpline spline(windingPath(true));
    constexpr float h = 1e-3f;
    const float start = spline.startTime(), end = spline.endTime();
    const glm::vec3 left = (spline.sample(end).position - spline.sample(end - h).position) / h;
    const glm::vec3 right = (spline.sample(start + h).position - spline.sample(start).position) / h;
    expectSameDirectionAndSpeed(left, right, 0.02f, "velocity at the seam", start);
    // Also where the closing segment begins (the last key).
    expectSameDirectionAndSpeed(velocityLeft(spline, 4.0f, h), velocityRight(spline, 4.0f, h), 0.02f,
                                "velocity", 4.0f);
    const glm::vec3 wLeft =
        angularVelocity(spline.sample(end - h).orientation, spline.sample(end).orientation, h);
    const glm::vec3 wRight =
        angularVelocity(spline.sample(start).orientation, spline.sample(start + h).orientation, h);
    expectSameDirectionAndSpeed(wLeft, wRight, 0.02f, "angular velocity at the seam", start);
}

TEST(CameraSpline, ConstantSpeedKeepsSpeedWithinTwoPercentOnVeryUnevenKeys) {
    CameraPath path;
    path.constantSpeed = true;
    // Keys 0.1 to 15 units apart, at even times, with a sharp bend.
    path.keyframes = {
        {0.0f, {0, 0, 0}, yaw(0), 0.8f},       {1.0f, {0.1f, 0, 0}, yaw(0), 0.8f},
        {2.0f, {0.3f, 0, 0.1f}, yaw(0), 0.8f}, {3.0f, {15, 0, 2}, yaw(0), 0.8f},
        {4.0f, {15, 3, 12}, yaw(0), 0.8f},     {5.0f, {14.5f, 3, 12.2f}, yaw(0), 0.8f},
        {6.0f, {-10, 0, 14}, yaw(0), 0.8f},
    };
    const CameraSpline spline(path);
    const float expected = spline.length() / spline.duration();
    constexpr int steps = 3000;
    const float dt = spline.duration() / steps;
    float lo = 1e9f, hi = 0.0f;
    for (int i = 0; i < steps; ++i) {
        const float t = i * dt;
        const float speed = glm::distance(spline.sample(t + dt).position, spline.sample(t).position) / dt;
        lo = std::min(lo, speed);
        hi = std::max(hi, speed);
    }
    EXPECT_GT(lo, 0.98f * expected) << "expected " << expected;
    EXPECT_LT(hi, 1.02f * expected) << "expected " << expected;

    // Played at the keys' times, the same path is anything but constant.
    path.constantSpeed = false;
    const CameraSpline timed(path);
    float timedLo = 1e9f, timedHi = 0.0f;
    for (int i = 0; i < steps; ++i) {
        const float t = i * dt;
        const float speed = glm::distance(timed.sample(t + dt).position, timed.sample(t).position) / dt;
        timedLo = std::min(timedLo, speed);
        timedHi = std::max(timedHi, speed);
    }
    EXPECT_GT(timedHi, 10.0f * timedLo);
}

TEST(CameraSpline, OrientationNeverFlipsWhenKeysHaveOppositeSigns) {
    CameraPath path;
    for (int i = 0; i < 8; ++i) {
        glm::quat q = yaw(0.4f * i) * glm::angleAxis(0.1f * i, glm::vec3(1, 0, 0));
        if (i % 2 == 1)
            q = -q; // the same rotation, the other hemisphere
        path.keyframes.push_back({0.5f * i, {float(i), 0, 0}, q, 0.8f});
    }
    for (const bool closed : {false, true}) {
        path.closed = closed;
        const CameraSpline spline(path);
        constexpr int steps = 4000;
        const float dt = spline.duration() / steps;
        glm::quat previous = spline.sample(0.0f).orientation;
        float largest = 0.0f;
        int signChanges = 0;
        for (int i = 1; i <= steps; ++i) {
            const glm::quat q = spline.sample(i * dt).orientation;
            largest = std::max(largest, rotationAngle(previous, q));
            signChanges += glm::dot(previous, q) < 0.0f;
            previous = q;
        }
        // Keys turn by about 0.41 rad per 0.5 s: a few milliradians per step.
        EXPECT_LT(largest, 0.01f) << (closed ? "closed" : "open");
        if (!closed) {
            EXPECT_EQ(signChanges, 0) << "the output quaternion keeps its sign along an open path";
        }
    }
}

TEST(CameraSpline, ATurnOfMoreThan180DegreesGoesTheShortWayPerSegment) {
    // Yaw 0, 100, 200, 300 degrees, stored with w >= 0: from 100 to 200 the
    // quaternions lie in opposite hemispheres (dot < 0).
    CameraPath path;
    for (int i = 0; i < 4; ++i)
        path.keyframes.push_back(
            {float(i), {0, 0, float(i)}, canonical(yaw(glm::radians(100.0f * i))), 0.8f});
    ASSERT_LT(glm::dot(path.keyframes[1].orientation, path.keyframes[2].orientation), 0.0f);
    const CameraSpline spline(path);
    for (int segment = 0; segment < 3; ++segment) {
        float turned = 0.0f;
        glm::quat previous = spline.sample(float(segment)).orientation;
        for (int i = 1; i <= 500; ++i) {
            const glm::quat q = spline.sample(segment + i / 500.0f).orientation;
            turned += rotationAngle(previous, q);
            previous = q;
        }
        EXPECT_NEAR(glm::degrees(turned), 100.0f, 10.0f) << "segment " << segment;
        // Half way the camera looks half way round.
        const glm::vec3 forward = forwardOf(spline.sample(segment + 0.5f).orientation);
        const glm::vec3 expected = forwardOf(yaw(glm::radians(100.0f * segment + 50.0f)));
        EXPECT_GT(glm::dot(forward, expected), std::cos(glm::radians(10.0f))) << "segment " << segment;
    }
}

TEST(CameraSpline, AClosedOrbitTurnsFullCircleWithoutAJump) {
    // 360 degrees in four keys: the quaternion comes back as -q at the seam.
    CameraPath path;
    path.closed = true;
    for (int i = 0; i < 4; ++i) {
        const float a = glm::radians(90.0f * i);
        path.keyframes.push_back({float(i), {5 * std::sin(a), 1, 5 * std::cos(a)}, canonical(yaw(a)), 0.8f});
    }
    const CameraSpline spline(path);
    EXPECT_FLOAT_EQ(spline.duration(), 4.0f);
    constexpr int steps = 2000;
    float largest = 0.0f, turned = 0.0f;
    glm::quat previous = spline.sample(0.0f).orientation;
    for (int i = 1; i <= steps; ++i) {
        const glm::quat q = spline.sample(4.0f * i / steps).orientation;
        const float step = rotationAngle(previous, q);
        largest = std::max(largest, step);
        turned += step;
        previous = q;
    }
    EXPECT_LT(largest, 0.01f);
    EXPECT_NEAR(glm::degrees(turned), 360.0f, 5.0f);
}

TEST(CameraSpline, TimeClampsOnOpenPathsAndWrapsOnClosedOnes) {
    CameraPath path = windingPath(false);
    for (auto& k : path.keyframes)
        k.time += 2.0f; // keys from t = 2
    const CameraSpline open(path);
    EXPECT_EQ(open.startTime(), 2.0f);
    EXPECT_EQ(open.sample(-5.0f).position, path.keyframes.front().position);
    EXPECT_EQ(open.sample(100.0f).position, path.keyframes.back().position);
    EXPECT_EQ(open.sample(-5.0f).time, -5.0f) << "the time asked for is reported";

    path.closed = true;
    const CameraSpline closed(path);
    const float period = closed.duration();
    for (const float t : {2.3f, 3.1f, 5.9f})
        for (const float shift : {-2.0f, -1.0f, 1.0f, 3.0f}) {
            const glm::vec3 a = closed.sample(t).position;
            const glm::vec3 b = closed.sample(t + shift * period).position;
            EXPECT_LT(glm::distance(a, b), 1e-3f) << t << " + " << shift << " periods";
        }
}

TEST(CameraSpline, NoKeysOrOneKeyIsAConstantCamera) {
    const CameraSpline empty(CameraPath{});
    EXPECT_EQ(empty.duration(), 0.0f);
    EXPECT_EQ(empty.keyCount(), 0u);
    EXPECT_EQ(empty.sample(3.0f).position, CameraKeyframe{}.position);
    Camera base;
    base.position = {1, 2, 3};
    base.nearPlane = 0.3f;
    EXPECT_EQ(empty.cameraAt(1.0f, base), base);

    CameraPath one;
    one.keyframes = {{4.0f, {1, 2, 3}, yaw(1.0f), 0.6f}};
    for (const bool closed : {false, true})
        for (const bool constantSpeed : {false, true}) {
            one.closed = closed;
            one.constantSpeed = constantSpeed;
            const CameraSpline spline(one);
            EXPECT_EQ(spline.duration(), 0.0f);
            for (const float t : {-1.0f, 4.0f, 9.0f}) {
                const CameraKeyframe k = spline.sample(t);
                EXPECT_EQ(k.position, one.keyframes[0].position);
                EXPECT_EQ(k.orientation, one.keyframes[0].orientation);
                EXPECT_EQ(k.fovY, 0.6f);
            }
        }
}

TEST(CameraSpline, KeysAtTheSameTimeMakeACut) {
    CameraPath path;
    path.keyframes = {{0.0f, {0, 0, 0}, yaw(0), 0.8f},
                      {1.0f, {1, 0, 0}, yaw(0.5f), 0.8f},
                      {1.0f, {10, 0, 0}, yaw(2.0f), 0.5f},
                      {2.0f, {11, 0, 0}, yaw(2.5f), 0.5f}};
    for (const bool closed : {false, true})
        for (const bool constantSpeed : {false, true}) {
            path.closed = closed;
            path.constantSpeed = constantSpeed;
            const CameraSpline spline(path);
            for (int i = 0; i <= 400; ++i) {
                const CameraKeyframe k = spline.sample(spline.duration() * i / 400.0f);
                ASSERT_TRUE(std::isfinite(k.position.x) && std::isfinite(k.orientation.w) &&
                            std::isfinite(k.fovY))
                    << i;
            }
        }
    path.closed = false;
    path.constantSpeed = false;
    const CameraSpline spline(path);
    EXPECT_LT(glm::distance(spline.sample(0.999f).position, glm::vec3(1, 0, 0)), 0.01f);
    EXPECT_EQ(spline.sample(1.0f).position, glm::vec3(10, 0, 0)) << "the later key holds from the cut on";
    EXPECT_EQ(spline.sample(1.0f).fovY, 0.5f);
}

TEST(CameraSpline, FieldOfViewNeverOvershootsItsKeys) {
    CameraPath path;
    const float fovs[] = {0.3f, 0.3f, 1.5f, 1.5f, 0.2f, 1.0f};
    const float times[] = {0.0f, 0.4f, 2.0f, 2.3f, 4.0f, 4.2f};
    for (int i = 0; i < 6; ++i)
        path.keyframes.push_back({times[i], {float(i), 0, 0}, yaw(0), fovs[i]});
    const CameraSpline spline(path);
    for (int i = 0; i <= 1000; ++i) {
        const float fov = spline.sample(spline.duration() * i / 1000.0f).fovY;
        EXPECT_GE(fov, 0.2f - 1e-6f);
        EXPECT_LE(fov, 1.5f + 1e-6f);
    }
}

TEST(CameraSpline, KeyframeFromCameraReproducesTheView) {
    Camera camera;
    camera.position = {2, 3, -4};
    camera.target = {-1, 0.5f, 2};
    camera.up = {0.1f, 1, 0};
    camera.fovY = 0.7f;
    const CameraKeyframe k = keyframeFromCamera(camera, 1.5f);
    EXPECT_EQ(k.time, 1.5f);
    EXPECT_EQ(k.position, camera.position);
    EXPECT_EQ(k.fovY, 0.7f);
    EXPECT_NEAR(glm::length(k.orientation), 1.0f, 1e-6f);

    CameraPath path;
    path.keyframes = {k};
    const Camera back = CameraSpline(path).cameraAt(0.0f, camera);
    const glm::mat4 a = camera.view(), b = back.view();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            EXPECT_NEAR(a[c][r], b[c][r], 1e-5f) << c << "," << r;
    EXPECT_EQ(back.nearPlane, camera.nearPlane);
    EXPECT_EQ(back.farPlane, camera.farPlane);

    // Looking straight down with up = +Y: still a valid orientation.
    Camera down;
    down.position = {0, 5, 0};
    down.target = {0, 0, 0};
    const CameraKeyframe d = keyframeFromCamera(down, 0.0f);
    EXPECT_GT(glm::dot(forwardOf(d.orientation), glm::vec3(0, -1, 0)), 0.9999f);
}

TEST(CameraSpline, AxesFollowOpenGLConventions) {
    EXPECT_EQ(forwardOf(glm::quat(1, 0, 0, 0)), glm::vec3(0, 0, -1));
    EXPECT_EQ(upOf(glm::quat(1, 0, 0, 0)), glm::vec3(0, 1, 0));
    // A quarter turn left (positive yaw about +Y) looks down -X.
    EXPECT_GT(glm::dot(forwardOf(yaw(kPi / 2)), glm::vec3(-1, 0, 0)), 0.9999f);
}
