// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// EXPECT_THROW_REASON(statement, type, phrase): `statement` throws `type` whose what()
// contains `phrase` (the reason, not only the kind: EXPECT_THROW would pass for any refusal
// of that type, e.g. a size check that fires before the check under test).

#ifndef TVF_TEST_EXPECT_REASON_H
#define TVF_TEST_EXPECT_REASON_H

#include <gtest/gtest.h>

#include <exception>
#include <string>

#define EXPECT_THROW_REASON(statement, type, phrase)                                                     \
  do                                                                                                     \
  {                                                                                                      \
    const std::string tvf_phrase_ = (phrase);                                                            \
    try                                                                                                  \
    {                                                                                                    \
      statement;                                                                                         \
      ADD_FAILURE() << #statement " threw nothing; expected " #type " with \"" << tvf_phrase_ << "\"";   \
    }                                                                                                    \
    catch(const type& tvf_error_)                                                                        \
    {                                                                                                    \
      EXPECT_NE(std::string(tvf_error_.what()).find(tvf_phrase_), std::string::npos)                    \
          << #statement " threw \"" << tvf_error_.what() << "\", not about \"" << tvf_phrase_ << "\"";   \
    }                                                                                                    \
    catch(const std::exception& tvf_error_)                                                              \
    {                                                                                                    \
      ADD_FAILURE() << #statement " threw another type than " #type ": " << tvf_error_.what();           \
    }                                                                                                    \
  } while(false)

#endif // TVF_TEST_EXPECT_REASON_H
