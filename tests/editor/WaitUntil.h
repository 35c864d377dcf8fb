#pragma once
// Waits for a condition while Qt delivers events, and fails the GoogleTest
// test when it is still false after the timeout. QtTest's QTRY_* macros are
// not usable here: under GoogleTest a timeout returns from the test
// silently, so the test passed without running its remaining checks.
#include <QTest>
#include <gtest/gtest.h>

// Only in a function returning void (a TEST body), like every ASSERT_*.
#define LPV_WAIT_UNTIL(condition, timeoutMs)                                                          \
    ASSERT_TRUE(QTest::qWaitFor([&] { return bool(condition); }, (timeoutMs)))                         \
        << "still false after " << (timeoutMs) << " ms: " #condition
