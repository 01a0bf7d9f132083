:- module(oro_memory,
          [ oro_memory_profile/2,       % +Name, -Profile
            oro_memory_lifetime/2,      % +Profile, -Milliseconds
            oro_memory_remember/3,      % +Model, +Profile, +Triples
            oro_memory_reset/0,
            oro_memory_deadlines/2,     % +Model, -Deadlines
            oro_memory_sync/0,
            oro_memory_restore/0
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(error)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(heaps)).
:- use_module(library(pairs)).
:- use_module(library(settings)).
:- use_module(library(debug)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/oro_persist)).
:- use_module(library(rbtrees)).

/** <module> Memory profiles: facts that fade

A fact added with the `shortterm` profile lives 10 time units, with
`episodic` 300; `longterm` (also `default`) facts are never forgotten.
A fact may also be given a lifespan of its own, lifespan(Units) (any
positive number of units: seconds at the default time base), as the
KB-API's `lifespan` asks; such facts live in the graph of a fourth
profile, `timed`.  One unit is the `time_base` setting (1000 ms;
`--time-base`).

Each profile is a graph of its own in each model (oro_store), so a
fact lives as long as any of its assertions: re-adding a long-term fact
as short-term changes nothing, re-adding a short-term fact refreshes its
deadline, and a fact added both as short-term and episodic stays until
the later deadline.  Only the deadline of each (model, profile, fact)
is kept here; nothing is reified in the store.

Deadlines are dynamic facts indexed on the deadline, so the facts due
at a given time are found without looking at the others.  A scheduler
thread owns a heap of the deadlines of each batch of facts added
together (Deadline-(Model-Profile)) and sleeps until the earliest one
(no polling).  When deadlines pass it pops them, and for each model
and profile removes the facts whose deadline is one of those, in one
store transaction: forgetting is a change like any other, seen by the
reasoner and by event watchers.  The facts are picked inside that
transaction, under the store's write lock, like the deadlines that
adding a fact sets or refreshes, so a fact refreshed after its old
deadline was popped is never forgotten by it.  A wake-up costs
O(log n) per due heap entry and O(1) per due fact, n the number of
entries pending; facts not due are never looked at.  A deadline is
never acted on before it is reached; at the default time base a fact
is gone a few milliseconds after.  Tests may set the module's clock
(set_test_clock/1) to drive forgetting without waiting.
*/

:- setting(time_base, positive_integer, 1000,
           'Length of one memory time unit, in milliseconds').

:- dynamic
    expiry/6,                       % DeadlineMs, Model, Profile, S, P, O
    test_clock/1.                   % Milliseconds

%!  oro_memory_profile(+Name, -Profile) is det.
%
%   Profile (`longterm`, `shortterm` or `episodic`) named by Name, in
%   any case; `default` and unknown names are `longterm` (ORO-SPEC §9).
%   Name may also be lifespan(Units), Units a positive number of time
%   units, which is its own Profile.
%
%   @error domain_error(oro_lifespan, Units) for a lifespan that is
%          not a positive number.

oro_memory_profile(Spec, Profile) :-
    compound(Spec),
    Spec = lifespan(Units),
    !,
    (   number(Units),
        Units > 0
    ->  Profile = Spec
    ;   domain_error(oro_lifespan, Units)
    ).
oro_memory_profile(Name, Profile) :-
    must_be(text, Name),
    atom_string(Atom0, Name),
    downcase_atom(Atom0, Atom),
    (   memberchk(Atom, [shortterm, episodic])
    ->  Profile = Atom
    ;   Profile = longterm
    ).

%!  oro_memory_lifetime(+Profile, -Milliseconds) is semidet.
%
%   How long a fact of Profile lives; fails for `longterm`.

oro_memory_lifetime(Profile, Ms) :-
    profile_units(Profile, Units),
    setting(time_base, Base),
    Ms is ceiling(Units * Base).

profile_units(lifespan(Units), Units) :-
    !.

profile_units(shortterm, 10).
profile_units(episodic, 300).

%!  oro_memory_remember(+Model, +Profile, +Triples) is det.
%
%   Start (or restart) the lifetime in Profile of the Triples that were
%   just asserted in the Profile graph of Model.  Long-term triples and
%   triples that were not stored in that graph (they live forever) are
%   ignored.  A lifespan(Units) sets the deadline of its triples in the
%   `timed` graph, replacing the one they had there.  Must run inside
%   oro_store_write/2, so that setting a deadline and forgetting are
%   serialised.

oro_memory_remember(Model, Profile0, Triples) :-
    (   oro_memory_lifetime(Profile0, Lifetime)
    ->  now_ms(Now),
        Deadline is ceiling(Now) + Lifetime,
        oro_profile_layer(Profile0, Profile),
        oro_graph(Model, profile(Profile), Graph),
        findall(deadline(Model, Profile, S, P, Stored, Deadline),
                ( member(rdf(S, P, O), Triples),
                  stored_triple(Graph, S, P, O, Stored)
                ),
                Entries0),
        sort(Entries0, Entries),
        (   Entries == []
        ->  true
        ;   maplist(oro_persist_record, Entries),
            with_mutex(oro_memory, maplist(set_deadline, Entries)),
            scheduler_send(schedule(Deadline, Model, Profile))
        )
    ;   true
    ).

%   stored_triple(+Graph, +S, +P, +O, -Stored): the triple S P O is in
%   Graph as S P Stored: a literal may be stored spelled as another
%   one of the same value (oro_stored_term/4).

stored_triple(Graph, S, P, O, Stored) :-
    oro_stored_term(S, P, O, Stored),
    rdf(S, P, Stored, Graph),
    !.

%   set_deadline(+Record): Record is deadline(Model, Profile, S, P, O,
%   Deadline), the form journaled by oro_persist.  The lookup by fact
%   uses the just-in-time index of S, P or O.

set_deadline(deadline(Model, Profile, S, P, O, Deadline)) :-
    retractall(expiry(_, Model, Profile, S, P, O)),
    assertz(expiry(Deadline, Model, Profile, S, P, O)).

%!  oro_memory_deadlines(+Model, -Deadlines) is det.
%
%   Deadlines are the pending Deadline-rdf(S,P,O)-Profile of Model, in
%   milliseconds since the epoch, earliest first.
%
%   @error existence_error(agent, Model) for an unknown model.

oro_memory_deadlines(Model0, Deadlines) :-
    oro_resolve_model(Model0, Model),
    findall(D-rdf(S, P, O)-Profile, expiry(D, Model, Profile, S, P, O),
            Deadlines0),
    keysort(Deadlines0, Deadlines).

%!  oro_memory_reset is det.
%
%   Forget every deadline (reset).  The scheduler drops them with its
%   heap, so that no deadline set meanwhile is left without an entry.

oro_memory_reset :-
    scheduler_call(reset).

%!  oro_memory_restore is det.
%
%   After a database directory was attached (oro_persist): give every
%   short-term and episodic fact found in the models its deadline
%   again, as committed with the fact, and forget at once those whose
%   deadline has passed.  A fact whose deadline record is missing gets
%   a full lifetime from now; one that had a lifespan of its own
%   (`timed`) is forgotten.

oro_memory_restore :-
    oro_persist_records(Records),
    rb_empty(Known0),
    foldl(record_deadline, Records, Known0, Known),
    now_ms(NowMs),
    Now is ceiling(NowMs),
    findall(deadline(Model, Profile, S, P, O, D),
            ( oro_model(Model),
              member(Profile, [shortterm, episodic, timed]),
              oro_graph(Model, profile(Profile), Graph),
              rdf(S, P, O, Graph),
              (   rb_lookup(Model-Profile-S-P-O, D0, Known)
              ->  D = D0
              ;   oro_memory_lifetime(Profile, Lifetime)
              ->  D is Now + Lifetime
              ;   D = Now                   % a lifespan of its own, lost
              )
            ),
            Entries),
    with_mutex(oro_memory, maplist(set_deadline, Entries)),
    findall(D-(Model-Profile), member(deadline(Model, Profile, _, _, _, D), Entries),
            Keys0),
    sort(Keys0, Keys),
    forall(member(D-(Model-Profile), Keys),
           scheduler_send(schedule(D, Model, Profile))),
    oro_memory_sync.

record_deadline(deadline(Model, Profile, S, P, O, D), T0, T) :-
    !,
    rb_insert(T0, Model-Profile-S-P-O, D, T).
record_deadline(_, T, T).

%   The deadlines still pending are the records a compacted commit log
%   keeps (oro_persist).

:- multifile oro_persist:live_records/1.

oro_persist:live_records(Records) :-
    findall(deadline(Model, Profile, S, P, O, D),
            expiry(D, Model, Profile, S, P, O),
            Records).

%!  oro_memory_sync is det.
%
%   Wait until the scheduler has handled every deadline already due.

oro_memory_sync :-
    scheduler_call(sync).

		 /*******************************
		 *            CLOCK             *
		 *******************************/

%   now_ms(-Milliseconds): the time since the epoch, from the system
%   clock unless a test set the clock (set_test_clock/1).

now_ms(Ms) :-
    (   test_clock(Ms0)
    ->  Ms = Ms0
    ;   get_time(Now),
        Ms is Now * 1000
    ).

%   set_test_clock(+Clock): for tests only.  Clock is a time in
%   milliseconds since the epoch, which the memory module then takes for
%   "now" (deadlines are set and acted on by it) until it is set again,
%   or `system` for the system clock.  The new time is asserted before
%   the old one is retracted, so that the scheduler never sees the
%   system clock meanwhile.  The scheduler looks at the clock again at
%   once; a test drives forgetting with set_test_clock/1 and
%   oro_memory_sync/0.

set_test_clock(Clock) :-
    (   Clock == system
    ->  retractall(test_clock(_))
    ;   must_be(integer, Clock),
        asserta(test_clock(Clock), Ref),
        forall(clause(test_clock(_), true, Old),
               (   Old == Ref
               ->  true
               ;   erase(Old)
               ))
    ),
    scheduler_send(wake).

		 /*******************************
		 *           SCHEDULER          *
		 *******************************/

%   The scheduler's heap holds Deadline-(Model-Profile) entries, one per
%   batch of facts added together.  When an entry is due, the facts of
%   that model and profile whose deadline is still that one are
%   forgotten; an entry whose facts were refreshed or forgotten since
%   finds none.

scheduler_send(Message) :-
    ensure_scheduler,
    thread_send_message(oro_memory_queue, Message).

scheduler_call(Request) :-
    ensure_scheduler,
    thread_self(Me),
    gensym(oro_memory_reply_, Tag),
    thread_send_message(oro_memory_queue, call(Request, Me, Tag)),
    thread_get_message(reply(Tag, done)).

ensure_scheduler :-
    (   catch(thread_property(oro_memory, status(running)), _, fail)
    ->  true
    ;   with_mutex(oro_memory,
                   (   catch(thread_property(oro_memory, status(running)),
                             _, fail)
                   ->  true
                   ;   (   catch(message_queue_property(oro_memory_queue,
                                                        size(_)), _, fail)
                       ->  true
                       ;   message_queue_create(_, [alias(oro_memory_queue)])
                       ),
                       catch(thread_join(oro_memory, _), _, true),
                       thread_create(scheduler, _, [alias(oro_memory)])
                   ))
    ).

%   A scheduler (re)started finds its heap in the deadlines pending.

scheduler :-
    with_mutex(oro_memory,
               findall(D-(Model-Profile),
                       expiry(D, Model, Profile, _, _, _),
                       Pairs0)),
    sort(Pairs0, Pairs),
    list_to_heap(Pairs, Heap),
    scheduler(Heap).

scheduler(Heap0) :-
    next_timeout(Heap0, Options),
    (   thread_get_message(oro_memory_queue, Message, Options)
    ->  catch(handle(Message, Heap0, Heap1), E,
              ( print_message(error, E), Heap1 = Heap0 ))
    ;   Heap1 = Heap0
    ),
    catch(expire_due(Heap1, Heap), E2,
          ( print_message(error, E2), Heap = Heap1 )),
    scheduler(Heap).

next_timeout(Heap, Options) :-
    (   min_of_heap(Heap, Deadline, _)
    ->  now_ms(Now),
        Wait is max(0, (Deadline - Now) / 1000),
        Options = [timeout(Wait)]
    ;   Options = []
    ).

handle(schedule(Deadline, Model, Profile), Heap0, Heap) :-
    add_to_heap(Heap0, Deadline, Model-Profile, Heap).
handle(wake, Heap, Heap).
handle(call(reset, Thread, Tag), _, Heap) :-
    with_mutex(oro_memory, retractall(expiry(_, _, _, _, _, _))),
    empty_heap(Heap),
    thread_send_message(Thread, reply(Tag, done)).
handle(call(sync, Thread, Tag), Heap0, Heap) :-
    expire_due(Heap0, Heap),
    thread_send_message(Thread, reply(Tag, done)).

%   expire_due(+Heap0, -Heap): pop the entries that are due and forget,
%   model and profile after model and profile, the facts still due at
%   their deadlines.

expire_due(Heap0, Heap) :-
    now_ms(NowMs),
    Now is floor(NowMs),
    due(Heap0, Now, Due, Heap),
    (   Due == []
    ->  true
    ;   sort(Due, Pairs),
        group_pairs_by_key(Pairs, Groups),
        forall(member((Model-Profile)-Deadlines, Groups),
               expire(Model, Profile, Deadlines))
    ).

due(Heap0, Now, [Key-Deadline|Due], Heap) :-
    min_of_heap(Heap0, Deadline, Key),
    Deadline =< Now,
    !,
    get_from_heap(Heap0, _, _, Heap1),
    due(Heap1, Now, Due, Heap).
due(Heap, _, [], Heap).

%   expire(+Model, +Profile, +Deadlines): forget the facts of Model and
%   Profile whose deadline is one of Deadlines (popped from the heap),
%   as they are when the store's write lock is held.  No transaction is
%   made when no fact has these deadlines any more.

expire(Model, Profile, Deadlines) :-
    (   member(D, Deadlines),
        expiry(D, Model, Profile, _, _, _)
    ->  oro_store_write(forget(Model, Profile),
                        forget(Model, Profile, Deadlines))
    ;   true
    ).

%   forget(+Model, +Profile, +Deadlines): runs inside oro_store_write/2.
%   The deadlines are dropped with their facts, in the same critical
%   section as they are read.

forget(Model, Profile, Deadlines) :-
    with_mutex(oro_memory,
               findall(rdf(S, P, O),
                       ( member(D, Deadlines),
                         clause(expiry(D, Model, Profile, S, P, O), true, Ref),
                         erase(Ref)
                       ),
                       Triples)),
    (   Triples == []
    ->  true
    ;   oro_model(Model)
    ->  length(Triples, N),
        debug(oro(memory), 'Forgetting ~D ~w facts of ~q', [N, Profile, Model]),
        oro_store_forget(Model, Profile, Triples)
    ;   true
    ).
