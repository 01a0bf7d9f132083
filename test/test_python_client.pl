/*  The Python client's tests (clients/python/tests, Python unittest),
    run by python3 as a child process: each starts its own server on a
    free loopback port.  Skipped, with a notice, when python3 is absent.
*/

:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(process)).
:- use_module(library(readutil)).
:- use_module(library(pcre), [re_matchsub/4]).

%   python3_available: python3 is on the PATH; if not, say so.

python3_available :-
    (   absolute_file_name(path(python3), _,
                           [access(execute), file_errors(fail)])
    ->  true
    ;   print_message(informational,
                      format("python3 is not installed: the Python client's \c
                              tests are skipped", [])),
        format(user_error, "~nNotice: python3 is not installed: \c
                            test_python_client is skipped~n", []),
        fail
    ).

%   python_tests(-ExitCode, -Output): run every Python test (at most
%   300 s); Output is what unittest printed.

python_tests(Code, Output) :-
    test_checkout_path('clients/python', Dir),
    setup_call_cleanup(
        process_create(path(timeout),
                       [ '300', sh, '-c',
                         'exec python3 -m unittest discover -v -s tests -t tests 2>&1'
                       ],
                       [ cwd(Dir), stdout(pipe(Out)), process(Pid) ]),
        ( read_string(Out, _, Output),
          process_wait(Pid, exit(Code))
        ),
        close(Out)).

%   unittest_summary(+Output, -Ran, -Skipped): from `Ran N tests` and
%   the closing `OK (skipped=K)` line.

unittest_summary(Output, Ran, Skipped) :-
    (   re_matchsub("Ran (?<n>\\d+) tests?", Output, Sub, [])
    ->  number_string(Ran, Sub.n)
    ;   Ran = 0
    ),
    (   re_matchsub("skipped=(?<k>\\d+)", Output, Sub2, [])
    ->  number_string(Skipped, Sub2.k)
    ;   Skipped = 0
    ).

:- begin_tests(python_client, [condition(python3_available)]).

test(unittest) :-
    python_tests(Code, Output),
    unittest_summary(Output, Ran, Skipped),
    (   Code == 0,
        Ran > 0
    ->  Passed is Ran - Skipped,
        format(user_error, "~nPython client: ~d tests passed, ~d skipped~n",
               [Passed, Skipped]),
        (   Skipped > 0
        ->  forall(( split_string(Output, "\n", "", Lines),
                     member(Line, Lines),
                     sub_string(Line, _, _, _, "skipped")
                   ),
                   format(user_error, "  ~s~n", [Line]))
        ;   true
        )
    ;   format(user_error, "~n~s~n", [Output]),
        fail
    ).

:- end_tests(python_client).
