:- module(oro_reason_schema,
          [ schema/2,                  % +Model, -Key
            model_schema/3,            % +Name, -Model, -Key
            pinned/1,                  % :Goal
            oro_compile_schema/2,      % +Model, -Key
            oro_compiled_schema/2,     % +Model, -Key
            oro_shared_schema/2,       % +Model, -Key
            oro_with_shared_schema/3,  % +Model, -Key, :Goal
            oro_schema_pin/0,
            oro_schema_unpin/0,
            oro_schema_superclass/3,   % +Key, +Class, -Super
            oro_drop_schema/1,         % +Key
            oro_with_schemas/2         % +ModelKeys, :Goal
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(lists)).
:- use_module(library(debug)).
:- use_module(library(error)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/reason/oro_reason_tables)).

:- meta_predicate
    oro_with_schemas(+, 0),
    oro_with_shared_schema(+, -, 0),
    pinned(0).

/** <module> Reasoning: the schema cache and its pinned readers

Which schema tables (oro_reason_tables) answer for a model: schema/2
gives the key of the up-to-date tables of a model, compiling them once
per schema generation (oro_store bumps the generation on each schema
change) under the mutex `oro_schema`, or privately for a thread whose
own write changed the schema.  This module owns the cache of keys
(schema_key/3, the flag `oro_schema_key`) and the tables a schema
change retired while threads still read them (retired/1, the flag
`oro_schema_readers`, the mutex `oro_schema_pin`): a reader of the
shared tables runs in a *pinned region* (pinned/1), and retired tables
are emptied when the last reader leaves.

It also holds the public predicates for callers that manage schema
tables themselves (the events watcher evaluates each change with the
schema of that change): oro_compile_schema/2, oro_with_schemas/2,
oro_with_shared_schema/3 and the others of its export list.
*/

:- dynamic
    schema_key/3.                   % Model, Generation, Key

		 /*******************************
		 *            SCHEMA            *
		 *******************************/

%!  schema(+Model, -Key) is det.
%
%   Key identifies the up-to-date schema closure tables of Model,
%   compiling them if the schema changed since they were made.

schema(Model, Key) :-
    (   cached_schema(Model, Key0)
    ->  Key = Key0
    ;   oro_store_schema_pending
    ->  private_schema(Model, Key)
    ;   oro_schema_generation(Gen),
        with_mutex(oro_schema, compile_schema_once(Model, Gen, Key))
    ).

%!  model_schema(+Name, -Model, -Key) is det.
%
%   Model is the model Name
%   designates (a model or an alias: `default`, the robot id), Key its
%   shared schema tables, as schema/2 gives them; to be called in a
%   pinned region (pinned/1).  The entry of the public predicates,
%   which take a name as their caller wrote it.  A name that has tables
%   for the current schema is a model (tables are compiled for models
%   only, and a reset, which removes models, bumps the generation): it
%   is not resolved again, so that the small questions (is x a C?) cost
%   no more than with the model.  Raises existence_error(agent, Name) if
%   there is no such model.

model_schema(Name, Model, Key) :-
    (   atom(Name),
        cached_schema(Name, Key0)
    ->  Model = Name,
        Key = Key0
    ;   oro_resolve_model(Name, Model),
        schema(Model, Key)
    ).

%   cached_schema(+Model, -Key): the tables schema/2 would give without
%   compiling: those given for this thread (oro_with_schemas/2), else
%   the shared ones of the current generation, unless this thread's
%   write changed the schema (its tables are its own).

cached_schema(Model, Key) :-
    (   nb_current(oro_schema_keys, Keys),
        memberchk(Model-Key0, Keys)
    ->  Key = Key0
    ;   \+ oro_store_schema_pending,
        oro_schema_generation(Gen),
        schema_key(Model, Gen, Key)
    ).

%   The tables are kept for Gen only if no schema change started while
%   they were compiled (oro_store bumps the generation before a schema
%   change becomes visible and again once it is committed or rolled
%   back), so a cached key never holds a schema older or newer than its
%   generation.

compile_schema_once(Model, Gen, Key) :-
    (   schema_key(Model, Gen, Key0)
    ->  Key = Key0
    ;   flag(oro_schema_key, Key, Key+1),
        compile_schema(Model, Key),
        oro_schema_generation(Gen1),
        (   Gen1 == Gen
        ->  forall(retract(schema_key(Model, _, Old)),
                   drop_schema(Old)),
            assertz(schema_key(Model, Gen, Key)),
            debug(oro(reason), 'Schema of ~q compiled as ~q (generation ~q)',
                  [Model, Key, Gen])
        ;   drop_schema(Key)
        )
    ).

%   private_schema(+Model, -Key): the schema tables of Model for a
%   thread whose write has changed the schema (oro_store_schema_pending/0).
%   The generation is already bumped, but other threads do not see the
%   change yet: tables they compile for that generation lack it, and
%   tables this thread compiles must not reach them (the write may
%   still be rolled back).  So they are compiled for this thread alone,
%   once a generation, and kept in its global variable
%   oro_private_schemas (Model-Gen-Key), one a model; this thread
%   drops the older ones, and all of them when it ends.

private_schema(Model, Key) :-
    oro_schema_generation(Gen),
    (   nb_current(oro_private_schemas, Private)
    ->  true
    ;   Private = [],
        thread_at_exit(drop_private_schemas)
    ),
    (   memberchk(Model-Gen-Key0, Private)
    ->  Key = Key0
    ;   oro_compile_schema(Model, Key),
        (   selectchk(Model-_-Old, Private, Rest)
        ->  retract_schema(Old)
        ;   Rest = Private
        ),
        nb_setval(oro_private_schemas, [Model-Gen-Key|Rest])
    ).

drop_private_schemas :-
    (   nb_current(oro_private_schemas, Private)
    ->  forall(member(_-_-Key, Private), retract_schema(Key))
    ;   true
    ).

%!  oro_compile_schema(+Model, -Key) is det.
%
%   Compile the schema of Model as the calling thread sees the store
%   now (in a snapshot, for instance) into fresh tables identified by
%   Key, outside the shared cache.  Use it with oro_with_schemas/2 and
%   release it with oro_drop_schema/1.  The event watcher uses this to
%   evaluate each change with the schema of that very change.

oro_compile_schema(Model, Key) :-
    must_be(atom, Model),
    flag(oro_schema_key, Key, Key+1),
    compile_schema(Model, Key).

%!  oro_compiled_schema(+Model, -Key) is semidet.
%
%   Key identifies the shared schema tables of Model for the current
%   schema generation, if a thread has compiled them already; fails
%   otherwise.  Unlike the other predicates of this module it never
%   compiles: for the events monitor, which must stay cheap and does
%   something safe instead.  A caller that reads the tables with Key
%   must be in a pinned region, entered before this call (see
%   oro_schema_pin/0).

oro_compiled_schema(Model, Key) :-
    must_be(atom, Model),
    oro_schema_generation(Gen),
    schema_key(Model, Gen, Key),
    !.

%!  oro_shared_schema(+Model, -Key) is det.
%
%   Key identifies the shared schema tables of Model for the current
%   schema generation, compiled now if no thread has yet (the tables
%   every query of Model uses).  Once a schema change has replaced
%   them, they are freed as soon as no thread is in a pinned region
%   (see oro_with_shared_schema/3): a caller that reads them with Key
%   must do so in one.

oro_shared_schema(Model, Key) :-
    must_be(atom, Model),
    schema(Model, Key).

%!  oro_with_shared_schema(+Model, -Key, :Goal) is nondet.
%
%   Call Goal with Key, the schema tables of Model as
%   oro_shared_schema/2 gives them, in a pinned region: the tables of
%   Key are not freed while Goal runs or has choice points left, even
%   if a schema change replaces them meanwhile.

oro_with_shared_schema(Model, Key, Goal) :-
    must_be(atom, Model),
    pinned(with_shared_schema(Model, Key, Goal)).

with_shared_schema(Model, Key, Goal) :-
    schema(Model, Key),
    call(Goal).

%!  oro_schema_superclass(+Key, +Class, -Super) is nondet.
%
%   Super is a (reflexive, transitive) super-class of the atom Class
%   in the schema tables Key, as oro_subclass/3 enumerates them.

oro_schema_superclass(Key, Class, Super) :-
    must_be(atom, Class),
    sub_class_of(Key, Class, Super).

%!  oro_drop_schema(+Key) is det.
%
%   Release tables made by oro_compile_schema/2.

oro_drop_schema(Key) :-
    must_be(integer, Key),
    retract_schema(Key).

%!  oro_with_schemas(+ModelKeys, :Goal) is semidet.
%
%   Run Goal (once) with the schema tables of each Model-Key pair of
%   ModelKeys instead of the shared cache, in this thread.

oro_with_schemas(ModelKeys, Goal) :-
    must_be(list, ModelKeys),
    (   nb_current(oro_schema_keys, Old)
    ->  true
    ;   Old = []
    ),
    setup_call_cleanup(
        b_setval(oro_schema_keys, ModelKeys),
        once(Goal),
        b_setval(oro_schema_keys, Old)).

		 /*******************************
		 *        PINNED READERS        *
		 *******************************/

%   The shared tables of a key replaced by a schema change (retired)
%   must outlive every reader that was handed the key, in any thread.
%   A reader of shared tables runs in a *pinned region* (pinned/1):
%   the flag oro_schema_readers counts the regions entered and not yet
%   left, in all threads, and a key retired while it is not 0 waits in
%   retired/1 until the last reader leaves, which frees it.  The count and retired/1 are guarded by the
%   mutex oro_schema_pin.
%
%   Why no reader sees its tables vanish: a key is retired
%   (drop_schema/1) only after it has been taken out of schema_key/3
%   (or was never put there), so no thread is handed it afterwards;
%   and a reader counts itself in (pin/0) *before* schema/2 reads
%   schema_key/3.  The retirement reads the count under the mutex, and
%   so is ordered with each pin: a reader that pinned first is counted,
%   and the key waits until it unpins; a reader that pins afterwards
%   reads schema_key/3 after the key was taken out, and cannot get it.
%   Keys private to a thread (private_schema/2, oro_compile_schema/2,
%   oro_with_schemas/2) are freed by their owner and need no pin.
%
%   Under readers that overlap without end, retired tables wait for a
%   moment with no reader; a reader that leaves choice points open
%   holds its pin until they are cut.

:- dynamic retired/1.

%!  pinned(:Goal) is nondet.
%
%   Goal, possibly nondeterministic, in a pinned region, held while
%   Goal runs or has choice points.

pinned(Goal) :-
    setup_call_cleanup(pin, Goal, unpin).

%!  oro_schema_pin is det.
%!  oro_schema_unpin is det.
%
%   Enter and leave a pinned region (see oro_with_shared_schema/3) that
%   is not a goal: the events monitor holds one from the moment it
%   reads the shared tables' key until the end of the commit whose
%   triples it classifies with it.  Each pin must be matched by one
%   unpin, and both must run with signals blocked (sig_atomic/1), so
%   that the mutex they take is never left locked.

oro_schema_pin :-
    pin.

oro_schema_unpin :-
    unpin.

%   pin and unpin run in the setup and cleanup of setup_call_cleanup/3,
%   where signals wait, so mutex_lock/1 and mutex_unlock/1 are paired.
%   (Not flag/3, which meta-calls update_flag/3 under a global mutex,
%   nor with_mutex/2 of a conjunction, which is compiled at each call:
%   this is on the path of every query.)  The last reader takes the
%   retired keys, and frees their tables after unlocking.

pin :-
    mutex_lock(oro_schema_pin),
    get_flag(oro_schema_readers, N0),
    N is N0 + 1,
    set_flag(oro_schema_readers, N),
    mutex_unlock(oro_schema_pin).

unpin :-
    mutex_lock(oro_schema_pin),
    get_flag(oro_schema_readers, N0),
    N is N0 - 1,
    set_flag(oro_schema_readers, N),
    (   N =:= 0,
        retired(_)
    ->  findall(Key, retract(retired(Key)), Keys)
    ;   Keys = []
    ),
    mutex_unlock(oro_schema_pin),
    maplist(retract_schema, Keys).

%   drop_schema(+Key): retire the shared tables Key, out of
%   schema_key/3: freed now if no thread is in a pinned region, else
%   when the last one leaves.  Under with_mutex/2: it is called while a
%   query compiles the tables, where a signal (the query's time limit)
%   may come.

drop_schema(Key) :-
    with_mutex(oro_schema_pin, retire(Key, Free)),
    (   Free == true
    ->  retract_schema(Key)
    ;   true
    ).

retire(Key, Free) :-
    get_flag(oro_schema_readers, N),
    (   N =:= 0
    ->  Free = true
    ;   assertz(retired(Key)),
        Free = false
    ).
