// The grading specification's contract (@maa/protocol/grading): what an exercise's grading.json
// must be, checked at release and when a stored one is graded.
export {
    type GradingSpec,
    gradingSpecContract,
    gradingSpecIssues,
    type SubmissionGrade,
    submissionGradeContract,
} from '@maa/protocol/grading';
