"""The solution in words: the printed solution (`report`), the problem in words (`words`),
the step table, the hand solution (`steptable`), the force analysis's words (`forces`) and
the table of instantaneous centres (`centres`)."""
