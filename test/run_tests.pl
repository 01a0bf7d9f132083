/*  Run the whole test suite:

        swipl test/run_tests.pl

    Loads every test/test_*.pl, runs all units, prints a closing line
    `N passed, N failed` and exits 0 only if nothing failed.
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

%   A watchdog ends a run that hangs: after ORO_TEST_TIMEOUT seconds
%   (default 1200) it prints the threads and their stacks and exits 2,
%   so that a deadlock shows up as a failure with a diagnosis rather
%   than as a CI run that never ends.

start_watchdog :-
    (   getenv('ORO_TEST_TIMEOUT', Text),
        atom_number(Text, Limit)
    ->  true
    ;   Limit = 1200
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
    include(test_file, Entries, Files0),
    msort(Files0, Files),
    forall(member(F, Files),
           ( directory_file_path(Dir, F, Path),
             load_files(Path, [if(not_loaded)])
           )),
    (   run_tests
    ->  true
    ;   true
    ),
    summary(S),
    Failed is S.failed + S.failed_assertions + S.sto,
    format("~d passed, ~d failed~n", [S.passed, Failed]),
    thread_send_message(test_watchdog, done),
    (   Failed =:= 0
    ->  halt(0)
    ;   halt(1)
    ).

test_file(F) :-
    sub_atom(F, 0, _, _, test_),
    file_name_extension(_, pl, F).
