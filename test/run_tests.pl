/*  Run the whole test suite:

        swipl test/run_tests.pl

    Loads every test/test_*.pl, runs all units, prints a closing line
    `N passed, N failed` and exits 0 only if nothing failed.  Naming
    test files runs only those (while working on one area):

        swipl test/run_tests.pl test_protocol test_events.pl
*/

:- prolog_load_context(directory, Dir),
   atom_concat(Dir, '/../prolog', Lib),
   asserta(user:file_search_path(library, Lib)),
   asserta(user:file_search_path(oro_test, Dir)).

:- use_module(library(plunit)).
:- use_module(library(apply)).

:- initialization(main, main).

:- dynamic summary/1.

:- multifile user:message_hook/3.

user:message_hook(plunit(Summary), silent, _) :-
    is_dict(Summary),
    retractall(summary(_)),
    assertz(summary(Summary)),
    fail.

%   Errors that plunit does not count are failures too: a file that
%   does not load, a unit whose setup fails (its tests are then not
%   run at all), an error printed by a server thread during a test.
%   The failures plunit counts itself are not counted again, nor the
%   errors a test provokes on purpose: a test file captures those in
%   the threads for which it asserts user:capturing_messages(Thread).

:- dynamic user:capturing_messages/1.

user:message_hook(Term, error, _) :-
    \+ counted_by_plunit(Term),
    \+ ( thread_self(Me),
         user:capturing_messages(Me)
       ),
    flag(oro_test_errors, N, N+1),
    fail.

counted_by_plunit(plunit(failed(_, _, _, _))).
counted_by_plunit(plunit(failed_assertion(_, _, _, _, _, _, _))).
counted_by_plunit(plunit(sto(_, _, _))).
counted_by_plunit(plunit(sto(_, _))).

%   A watchdog ends a run that hangs: after ORO_TEST_TIMEOUT seconds
%   (default 900, the 15 minutes the README allows) it prints the
%   threads and their stacks and exits 2,
%   so that a deadlock shows up as a failure with a diagnosis rather
%   than as a CI run that never ends.

start_watchdog :-
    (   getenv('ORO_TEST_TIMEOUT', Text),
        atom_number(Text, Limit)
    ->  true
    ;   Limit = 900
    ),
    thread_create(watchdog(Limit), _, [alias(test_watchdog), detached(true)]).

watchdog(Limit) :-
    (   thread_get_message(test_watchdog, done, [timeout(Limit)])
    ->  true
    ;   format(user_error, "~nTest run exceeded ~w s: threads now:~n", [Limit]),
        forall(thread_property(T, status(S)),
               format(user_error, "  ~q: ~q~n", [T, S])),
        forall(( thread_property(T, status(running)), T \== test_watchdog ),
               catch(thread_signal(T, ( format(user_error, "~n-- ~q --~n", [T]),
                                        backtrace(30) )),
                     _, true)),
        sleep(2),
        format("0 passed, 1 failed (timeout after ~w s)~n", [Limit]),
        halt(2)
    ).

main :-
    start_watchdog,
    absolute_file_name(oro_test('.'), Dir, [file_type(directory)]),
    directory_files(Dir, Entries),
    include(test_file, Entries, Files1),
    current_prolog_flag(argv, Argv),
    selected_files(Argv, Files1, Files0),
    msort(Files0, Files),
    forall(member(F, Files),
           ( directory_file_path(Dir, F, Path),
             load_files(Path, [if(not_loaded)])
           )),
    (   run_tests
    ->  true
    ;   true
    ),
    (   summary(S)
    ->  true
    ;   S = _{passed:0, failed:0, failed_assertions:0, sto:0}
    ),
    flag(oro_test_errors, Errors, Errors),
    (   Errors > 0
    ->  format("~d error(s) outside the tests' own results (see above)~n",
               [Errors])
    ;   true
    ),
    Failed is S.failed + S.failed_assertions + S.sto + Errors,
    format("~d passed, ~d failed~n", [S.passed, Failed]),
    thread_send_message(test_watchdog, done),
    (   Failed =:= 0
    ->  halt(0)
    ;   halt(1)
    ).

%   selected_files(+Names, +Files, -Selected): the test files named on
%   the command line (with or without .pl), or all of them.

selected_files([], Files, Files) :-
    !.
selected_files(Names, Files, Selected) :-
    findall(F,
            ( member(Name, Names),
              file_name_extension(Base, _, Name),
              file_name_extension(Base, pl, F),
              (   memberchk(F, Files)
              ->  true
              ;   format(user_error, "No test file ~w~n", [F]),
                  halt(2)
              )
            ),
            Selected).

test_file(F) :-
    sub_atom(F, 0, _, _, test_),
    file_name_extension(_, pl, F).
